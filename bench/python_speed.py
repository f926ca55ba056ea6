#!/usr/bin/python3
"""The Python module's cost over the C++ call, and against shapely 1.8 (GEOS), on blob
n = 1e5 with numpy arrays in and out (issue 16). One process, one run: every timed
variant is repeated in turn (round robin) so that load from other processes falls on all
of them alike, and the medians and their ratios come from the same run.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_speed.py [--n 100000] [--repeats 15]

Writes bench/results/python_speed.{json,md,png} (or --out DIR). Timed variants, each the
intersection of the two blobs:

- cpp: mk::compute on inputs already converted, timed in C++ (the C++ call);
- module: mkbool.intersection(numpy A, numpy B) and the result's .polygons (every ring a
  numpy array): arrays in, arrays out;
- module_in_only: the same without reading the arrays out;
- shapely: Polygon(A).intersection(Polygon(B)) and every ring of the result as a numpy
  array: arrays in, arrays out;
- geos_only: the intersection of two shapely polygons built beforehand;
- module_nothing_kept: the module after mkbool.release_memory(), as in a process's first
  call (the module keeps the large blocks the library frees for its next call).

Before each shapely and GEOS round the module's kept blocks are released (untimed), so
that GEOS finds the heap as in a process without mkbool.

Then the cost of the exact values (exact area, exact coordinates, Fractions) asked for in
the call or afterwards, on the blobs and on two stars with many crossings (exact_costs).
"""

import argparse
import json
import math
import pathlib
import platform
import statistics
import time

import numpy as np
import shapely
import shapely.geometry as sg

import mkbool
from mkbool import _mkbool


def blob(n, centre, phase=0.0):
    # bench/workloads.cpp's blob_ring, operation for operation: t = 2 pi i / n,
    # r = 100 (1 + 0.1 sin(5 t + phase)), vertex (cx + r cos t, cy + r sin t).
    t = 2 * math.pi * np.arange(n, dtype=np.float64) / n
    r = 100 * (1 + 0.1 * np.sin(5 * t + phase))
    return np.column_stack([centre[0] + r * np.cos(t), centre[1] + r * np.sin(t)])


def shapely_arrays(g):
    parts = [g] if g.geom_type == "Polygon" else list(g.geoms)
    return [[np.asarray(p.exterior.coords)] + [np.asarray(h.coords) for h in p.interiors] for p in parts]


def star(n, radius, phase):
    # A star of n spikes (outer radius `radius`, inner radius radius / 2) turned by `phase`:
    # two of them turned by half a spike cross about 4n times, the case where the exact
    # area and exact coordinates cost more than the operation.
    t = 2 * math.pi * np.arange(2 * n, dtype=np.float64) / (2 * n) + phase
    r = np.where(np.arange(2 * n) % 2 == 0, radius, radius / 2)
    return np.column_stack([r * np.cos(t), r * np.sin(t)])


def exact_costs(args, a, b, report, md, out):
    """What the exact values cost (BooleanOptions::area_exact and exact_coordinates are
    opt-in since issue 17): the call without them, with them asked for in the call, and
    asked for afterwards from the result (the module runs the operation again once), and
    the Fractions built from the exact coordinates. Blob 1e5 (few crossings) and two stars
    of --star spikes (many crossings); medians of --exact-repeats round-robin rounds."""
    cases = {"blob": (a, b),
             "star": (star(args.star, 100.0, 0.0), star(args.star, 100.0, math.pi / (2 * args.star)))}
    rows, result = [], {}
    for name, (x, y) in cases.items():
        px, py = mkbool.as_polygon(x), mkbool.as_polygon(y)

        def timed(f):
            t0 = time.perf_counter()
            f()
            return time.perf_counter() - t0

        variants = {
            "plain": lambda: mkbool.intersection(px, py, kernel=args.kernel),
            "area_exact_in_call": lambda: mkbool.intersection(px, py, kernel=args.kernel, area_exact=True).area_exact,
            "area_exact_later": lambda: mkbool.intersection(px, py, kernel=args.kernel).area_exact,
            "exact_in_call": lambda: mkbool.intersection(px, py, kernel=args.kernel, exact=True)._r._exact_text,
            "exact_later": lambda: mkbool.intersection(px, py, kernel=args.kernel)._r._exact_text,
        }
        times = {k: [] for k in variants}
        for f in variants.values():
            f()
        for _ in range(args.exact_repeats):
            for k, f in variants.items():
                times[k].append(timed(f))
        r = mkbool.intersection(px, py, kernel=args.kernel, exact=True)
        fractions_s = timed(lambda: r.exact_rings)
        med = {k: statistics.median(v) for k, v in times.items()}
        med["fractions"] = fractions_s
        result[name] = {"median_s": med, "all_s": times, "crossings": r.stats["crossings"],
                        "vertices_out": r.stats["vertices_out"], "vertices_in": r.stats["vertices_in"]}
        rows.append(f"| {name} ({r.stats['vertices_in']} vertices in, {r.stats['crossings']} crossings) | "
                    f"{med['plain'] * 1e3:.1f} ms | "
                    f"{med['area_exact_in_call'] / med['plain']:.2f} | {med['area_exact_later'] / med['plain']:.2f} | "
                    f"{med['exact_in_call'] / med['plain']:.2f} | {med['exact_later'] / med['plain']:.2f} | "
                    f"{fractions_s * 1e3:.1f} ms |")
    report["exact_costs"] = result
    (out / "python_speed.json").write_text(json.dumps(report, indent=1) + "\n")
    md += ["", f"The exact values (opt-in), intersection with kernel `{args.kernel}`, medians of {args.exact_repeats} "
           "rounds; times relative to the call without them (`plain`): asked for in the call (`area_exact=True`, "
           "`exact=True`), or read from the result afterwards (`.area_exact`, the exact coordinates: the operation "
           "runs again once); the last column builds the `Fraction` pairs of `.exact_rings` from them.", "",
           "| case | plain | area_exact in call | .area_exact later | exact in call | exact later | Fractions |",
           "|---|---:|---:|---:|---:|---:|---:|"] + rows
    (out / "python_speed.md").write_text("\n".join(md) + "\n")
    print("\n".join(md[-len(rows) - 4:]))


def chain_costs(args, a, b, report, md, out):
    """What exact chaining costs: (A ∪ B) ∩ C with A ∪ B given as its exact result (the
    default for a Result operand: its crossings are rationals, so the next operation runs the
    rational kernel) or as its rounded polygons (.wkb), each converted once before timing;
    and making the exact input from a new result (.exact_polygon(): exact coordinates, one
    more run of the union). C is a third blob; medians of --exact-repeats rounds."""
    c = mkbool.as_polygon(blob(args.n, (15.0, 25.0), 0.7))
    ab = mkbool.union(a, b, kernel=args.kernel)
    exact_in, rounded_in = ab.exact_polygon(), mkbool.as_polygon(ab.wkb)
    variants = {
        "union": lambda: mkbool.union(a, b, kernel=args.kernel),
        "exact_polygon": lambda: mkbool.union(a, b, kernel=args.kernel).exact_polygon(),
        "from_rounded": lambda: mkbool.intersection(rounded_in, c, kernel=args.kernel),
        "from_exact": lambda: mkbool.intersection(exact_in, c, kernel=args.kernel),
    }
    times = {k: [] for k in variants}
    for _ in range(args.exact_repeats):
        for k, f in variants.items():
            t0 = time.perf_counter()
            f()
            times[k].append(time.perf_counter() - t0)
    med = {k: statistics.median(v) for k, v in times.items()}
    report["chain_costs"] = {"median_s": med, "all_s": times, "exact_input": exact_in.is_exact,
                             "crossings_of_union": ab.stats["crossings"]}
    (out / "python_speed.json").write_text(json.dumps(report, indent=1) + "\n")
    md += ["", f"Exact chaining, (A ∪ B) ∩ C on blobs (C a third blob), kernel `{args.kernel}`, medians of "
           f"{args.exact_repeats} rounds: A ∪ B ({ab.stats['crossings']} crossings, exact input "
           f"{'with rationals' if exact_in.is_exact else 'all doubles'}) {med['union'] * 1e3:.1f} ms, and its "
           f".exact_polygon() {med['exact_polygon'] * 1e3:.1f} ms including that union; the intersection with C "
           f"from the rounded union {med['from_rounded'] * 1e3:.1f} ms, from the exact one "
           f"{med['from_exact'] * 1e3:.1f} ms ({med['from_exact'] / med['from_rounded']:.1f}x: the rational kernel)."]
    (out / "python_speed.md").write_text("\n".join(md) + "\n")
    print(md[-1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=100000)
    ap.add_argument("--repeats", type=int, default=15)
    ap.add_argument("--kernel", default="exact")
    ap.add_argument("--star", type=int, default=2000, help="spikes of the stars of the exact-values table")
    ap.add_argument("--exact-repeats", type=int, default=5)
    ap.add_argument("--out", default=str(pathlib.Path(__file__).resolve().parent / "results"))
    args = ap.parse_args()

    a, b = blob(args.n, (0.0, 0.0)), blob(args.n, (30.0, 10.0))
    pa, pb = mkbool.as_polygon(a), mkbool.as_polygon(b)
    sa, sb = sg.Polygon(a), sg.Polygon(b)

    def cpp():
        return _mkbool._time_compute("intersection", pa, pb, args.kernel, 1)[0] / 1e9

    parts = {"convert_in": [], "call": [], "arrays_out": [], "op_ns": []}

    def module():
        # The whole of it (what a user gets), and its three parts: numpy to the library's
        # polygons, the call (the C++ call plus the result object), the result to numpy.
        t0 = time.perf_counter()
        pa2, pb2 = mkbool.as_polygon(a), mkbool.as_polygon(b)
        t1 = time.perf_counter()
        r = mkbool.intersection(pa2, pb2, kernel=args.kernel)
        t2 = time.perf_counter()
        r.polygons
        t3 = time.perf_counter()
        parts["convert_in"].append(t1 - t0)
        parts["call"].append(t2 - t1)
        parts["arrays_out"].append(t3 - t2)
        parts["op_ns"].append(r.stats["op_ns"] / 1e9)
        return t3 - t0

    def module_in_only():
        t0 = time.perf_counter()
        mkbool.intersection(a, b, kernel=args.kernel)
        return time.perf_counter() - t0

    def module_nothing_kept():
        # The module after release_memory(): no freed blocks kept from the last call, as in
        # the first call of a process.
        _mkbool.release_memory()
        t0 = time.perf_counter()
        r = mkbool.intersection(a, b, kernel=args.kernel)
        r.polygons
        return time.perf_counter() - t0

    def shapely_arrays_in_out():
        # GEOS runs on glibc's heap as in a process where mkbool kept nothing: the blocks
        # the module keeps between calls (python/src/memory.cpp) are handed back first,
        # since otherwise GEOS would find less free memory in the heap than without mkbool.
        _mkbool.release_memory()
        t0 = time.perf_counter()
        shapely_arrays(sg.Polygon(a).intersection(sg.Polygon(b)))
        return time.perf_counter() - t0

    def geos_only():
        _mkbool.release_memory()  # as for shapely_arrays_in_out
        t0 = time.perf_counter()
        sa.intersection(sb)
        return time.perf_counter() - t0

    # The order within a round: the variants that release the module's kept blocks first,
    # so that the C++ call and the module run alike with the blocks of the call before.
    variants = {"shapely": shapely_arrays_in_out, "geos_only": geos_only, "module_nothing_kept": module_nothing_kept,
                "cpp": cpp, "module": module, "module_in_only": module_in_only}
    for f in variants.values():  # warm up: caches, allocator, lazy imports
        f()
    times = {k: [] for k in variants}
    for _ in range(args.repeats):
        for k, f in variants.items():
            times[k].append(f())
    med = {k: statistics.median(v) for k, v in times.items()}
    med_parts = {k: statistics.median(v) for k, v in parts.items()}
    # Each round runs the variants back to back: the ratio within a round sees the same load.
    paired = {k: statistics.median(x / c for x, c in zip(times[k], times["cpp"])) for k in times}

    # Same answer: areas agree to rounding (GEOS computes in floating point).
    r = mkbool.intersection(a, b, kernel=args.kernel)
    g = sa.intersection(sb)
    out_vertices = sum(len(ring) - 1 for poly in r.polygons for ring in poly)
    report = {
        "n": args.n, "kernel": args.kernel, "repeats": args.repeats,
        "median_s": med, "all_s": times, "module_parts_median_s": med_parts, "module_parts_s": parts,
        "ratios": {
            "module_over_cpp": med["module"] / med["cpp"],
            "module_over_cpp_paired": paired["module"],
            "module_in_only_over_cpp_paired": paired["module_in_only"],
            "module_conversions_over_cpp": (med_parts["convert_in"] + med_parts["arrays_out"]) / med["cpp"],
            "module_over_shapely": med["module"] / med["shapely"],
            "module_over_shapely_paired": statistics.median(x / y for x, y in zip(times["module"], times["shapely"])),
            "module_nothing_kept_over_shapely_paired":
                statistics.median(x / y for x, y in zip(times["module_nothing_kept"], times["shapely"])),
            "cpp_over_geos_only": med["cpp"] / med["geos_only"],
        },
        "area": {"mkbool": r.area, "geos": g.area}, "vertices_out": out_vertices,
        "versions": {"python": platform.python_version(), "numpy": np.__version__, "shapely": shapely.__version__,
                     "geos": ".".join(map(str, shapely.geos.geos_version))},
        "load_average": list(__import__("os").getloadavg()),
        "date": time.strftime("%Y-%m-%d %H:%M"),
    }
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "python_speed.json").write_text(json.dumps(report, indent=1) + "\n")

    rows = [("C++ call (mk::compute, timed in C++)", "cpp"),
            ("module: numpy in, numpy out (.polygons)", "module"),
            ("module: numpy in, result object only", "module_in_only"),
            ("module: numpy in, numpy out, no blocks kept from the last call", "module_nothing_kept"),
            ("shapely 1.8: numpy in, numpy out", "shapely"),
            ("GEOS alone (shapely polygons built before)", "geos_only")]
    md = [f"Intersection of two blobs of n = {args.n} vertices each, kernel `{args.kernel}`; medians of "
          f"{args.repeats} round-robin repetitions in one process ({report['date']}, load average "
          f"{report['load_average'][0]:.1f} on {__import__('os').cpu_count()} cores), shapely "
          f"{report['versions']['shapely']} on GEOS {report['versions']['geos']}.", "",
          "| variant | median | / C++ call (medians) | / C++ call (median of per-round ratios) |",
          "|---|---:|---:|---:|"]
    for label, k in rows:
        md.append(f"| {label} | {med[k] * 1e3:.2f} ms | {med[k] / med['cpp']:.3f} | {paired[k]:.3f} |")
    ra = report["ratios"]
    md += ["", f"The module's own work (medians): numpy to polygons {med_parts['convert_in'] * 1e3:.2f} ms, result to "
           f"numpy arrays {med_parts['arrays_out'] * 1e3:.2f} ms: {100 * ra['module_conversions_over_cpp']:.1f}% of "
           f"the C++ call; the call itself (C++ call and result object) {med_parts['call'] * 1e3:.2f} ms, of which the "
           f"operation (BooleanStats::op_ns: the six steps) {med_parts['op_ns'] * 1e3:.2f} ms and the rest the library's "
           f"output (rounding, the exact validity check of the rounded output, the area).",
           f"Module overhead over the C++ call, arrays in and out: {100 * (ra['module_over_cpp_paired'] - 1):+.1f}% "
           f"(median of per-round ratios; {100 * (ra['module_over_cpp'] - 1):+.1f}% from the medians). "
           f"Module against shapely, arrays in and out: {ra['module_over_shapely_paired']:.2f}x the time "
           f"(per-round ratios; {ra['module_over_shapely']:.2f}x from the medians; "
           f"{ra['module_nothing_kept_over_shapely_paired']:.2f}x with no blocks kept); the C++ call against GEOS alone: "
           f"{ra['cpp_over_geos_only']:.2f}x.",
           f"Result: {out_vertices} vertices; area {r.area!r} (mkbool, exact area correctly rounded), "
           f"{g.area!r} (GEOS)."]
    (out / "python_speed.md").write_text("\n".join(md) + "\n")
    print("\n".join(md))

    exact_costs(args, a, b, report, md, out)
    chain_costs(args, a, b, report, md, out)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 2.8))
    labels = [label.split(" (")[0].replace(": ", ":\n") for label, _ in rows]
    values = [med[k] * 1e3 for _, k in rows]
    colours = ["#7570b3", "#1b9e77", "#66c2a5", "#d95f02", "#fc8d62"]
    ax.barh(labels[::-1], values[::-1], color=colours[::-1])
    for y, v in enumerate(values[::-1]):
        ax.text(v, y, f" {v:.1f} ms", va="center", fontsize=8)
    ax.set_xlabel("median wall time (ms)")
    ax.set_title(f"blob n = {args.n}, intersection, one run", fontsize=10)
    ax.set_xlim(0, max(values) * 1.2)
    ax.tick_params(axis="y", labelsize=8)
    fig.tight_layout()
    fig.savefig(out / "python_speed.png", dpi=100)


if __name__ == "__main__":
    main()
