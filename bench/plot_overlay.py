#!/usr/bin/python3
# Report of the overlay benchmark against peers: Markdown tables of median times and ratios,
# and log-log plots of time against n, one per workload, from Google Benchmark's JSON output.
# [BRIEF §6] (the anchors and the bar)
# Preconditions: JSON written by bin/bench_overlay --benchmark_out=FILE
# --benchmark_out_format=json (any --benchmark_repetitions); run with /usr/bin/python3
# (matplotlib from python3-matplotlib).
"""Usage: plot_overlay.py overlay.json --markdown overlay.md --plot overlay.png"""

import argparse
import json
import math
import re
import statistics
import sys
from collections import defaultdict

PEERS = [("GEOS", "GEOS"), ("BoostGeometry", "Boost.Geometry"), ("Clipper", "Clipper"),
         ("ClipperPolyTree", "Clipper PolyTree"), ("CgalEpeck", "CGAL Epeck")]
INEXACT_FAST_PEERS = ["GEOS", "BoostGeometry"]  # the bar's "fastest inexact peer"
TABLE_ROWS = [("blob", 100_000), ("blob", 1_000_000), ("blob", 10_000_000), ("star", 10_000), ("star", 20_000),
              ("stripes", 8_000), ("stripes", 125_000), ("checkerboard", 10_000), ("checkerboard", 100_000),
              ("checkerboard_shared", 10_000), ("checkerboard_shared", 100_000), ("checkerboard_offset", 10_000),
              ("checkerboard_offset", 100_000), ("many_holes", 10_000), ("many_holes", 100_000),
              ("long_spikes", 100_000), ("long_spikes", 1_000_000), ("nested_squares", 1_000),
              ("nested_squares", 100_000), ("nested_wavy_rings", 1_000), ("nested_wavy_rings", 4_000)]
OPERATIONS = ["intersection", "union", "difference", "xor"]
# Issue 14's comparison: every operation at these sizes, exact against the peers that return
# polygons with holes and Clipper.
EVERY_OP_PEERS = ["GEOS", "BoostGeometry", "Clipper", "ClipperPolyTree"]
SLOPE_BAR = 1.25  # issue 14: log-log slope of time against size (n + k), 10^3 to 10^6 vertices
WORKLOADS = ["blob", "star", "checkerboard", "nested_squares", "stripes", "checkerboard_shared",
             "checkerboard_offset", "many_holes", "long_spikes", "nested_wavy_rings"]
TABLE_OP = "intersection"
NAME = re.compile(r"^BM_Overlay<(?P<runner>[^>]+)>/(?P<workload>\w+)/(?P<op>\w+)/(?P<n>\d+)")
SUMMARY_END = "<!-- end of the summary: the README copies the text above -->"
README_BEGIN = "<!-- overlay results: written by bench/plot_overlay.py --readme -->"
README_END = "<!-- end of overlay results -->"
TOP_BEGIN = "<!-- speed summary: written by bench/plot_overlay.py --top-readme -->"
TOP_END = "<!-- end of speed summary -->"
COMPACT_PEERS = ["GEOS", "BoostGeometry", "Clipper", "ClipperPolyTree", "CgalEpeck"]
TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def load(path):
    """Per (runner, workload, op, n): median time in ms over repetitions, counters, error."""
    with open(path) as f:
        doc = json.load(f)
    times = defaultdict(list)
    counters = {}
    errors = {}
    for b in doc["benchmarks"]:
        if b.get("run_type") == "aggregate":
            continue  # medians are taken here from the repetitions themselves
        m = NAME.match(b.get("run_name", b["name"]))
        if not m:
            continue
        key = (m["runner"], m["workload"], m["op"], int(m["n"]))
        if b.get("error_occurred"):
            errors[key] = b.get("error_message", "error")
            continue
        times[key].append(b["real_time"] * TO_MS[b.get("time_unit", "ns")])
        counters.setdefault(key, []).append(b)
    medians = {k: statistics.median(v) for k, v in times.items()}
    runs = {k: len(v) for k, v in times.items()}
    last = {k: v[-1] for k, v in counters.items()}
    return doc.get("context", {}), medians, runs, last, errors


def load_parts(paths):
    """load() over the parts of one run: each later part replaces the workloads it holds."""
    context, medians, runs, counters, errors = load(paths[0])
    commits = [context.get("mkbool_commit", "?")]
    for path in paths[1:]:
        c2, m2, r2, k2, e2 = load(path)
        held = {k[1] for k in list(m2) + list(e2)}
        for d, d2 in ((medians, m2), (runs, r2), (counters, k2), (errors, e2)):
            for key in [k for k in d if k[1] in held]:
                del d[key]
            d.update(d2)
        commits.append(c2.get("mkbool_commit", "?"))
    if len(paths) > 1:
        context["mkbool_commit"] = " and ".join(commits)
        context["parts"] = len(paths)
    return context, medians, runs, counters, errors


def fmt_n(n):
    """1e5 rather than 100000 for powers of ten."""
    e = round(math.log10(n)) if n > 0 else 0
    return f"1e{e}" if n == 10 ** e else str(n)


def fmt_ms(ms):
    if ms is None:
        return "-"
    if ms >= 1000:
        return f"{ms / 1000:.2f} s"
    if ms >= 10:
        return f"{ms:.0f} ms"
    return f"{ms:.2g} ms"


def fmt_ratio(r):
    if r is None:
        return "-"
    return f"{r:.2g}x" if r < 10 else f"{r:.0f}x"


def kernels_of(medians, errors):
    names = {k[0] for k in list(medians) + list(errors) if k[0].startswith("mkbool:")}
    order = ["exact", "rational", "rational-mp", "rational-cpp", "adaptive", "interval", "cgal", "double"]
    return sorted(names, key=lambda n: (order.index(n[7:]) if n[7:] in order else len(order), n))


def cell(medians, errors, key):
    if key in medians:
        return fmt_ms(medians[key])
    if key in errors:
        return "error"
    return "not run"


NOT_RUN = ("*not run*: left out of the default run (bench/README.md, \"Limits of the default run\"); "
           "*error*: the runner reported an error (listed at the end of overlay.md).\n")


def markdown(context, medians, runs, counters, errors):
    kernels = kernels_of(medians, errors)
    out = []
    label = lambda r: r.replace("mkbool:", "mkbool `") + "`" if r.startswith("mkbool:") else dict(PEERS).get(r, r)
    reps = sorted(set(runs.values()))
    out.append(f"Operation: {TABLE_OP}. Median wall time over {'/'.join(map(str, reps))} runs "
               "(see bench/README.md for which cases run once); n is each workload's size "
               "(bench/README.md, Workloads).\n")
    header = ["workload"] + [p[1] for p in PEERS] + [label(k) for k in kernels]
    out.append("| " + " | ".join(header) + " |")
    out.append("|" + "---|" * len(header))
    for w, n in TABLE_ROWS:
        row = [f"{w}, n = {fmt_n(n)}"]
        row += [cell(medians, errors, (p, w, TABLE_OP, n)) for p, _ in PEERS]
        row += [cell(medians, errors, (k, w, TABLE_OP, n)) for k in kernels]
        out.append("| " + " | ".join(row) + " |")
    out.append("")
    out.append(NOT_RUN)

    out.append("Ratio: mkbool kernel's time / peer's time (below 1: mkbool is faster).\n")
    header = ["workload", "kernel"] + [p[1] for p in PEERS]
    out.append("| " + " | ".join(header) + " |")
    out.append("|" + "---|" * len(header))
    for w, n in TABLE_ROWS:
        for k in kernels:
            t = medians.get((k, w, TABLE_OP, n))
            if t is None:
                continue
            row = [f"{w}, n = {fmt_n(n)}", label(k)]
            for p, _ in PEERS:
                tp = medians.get((p, w, TABLE_OP, n))
                row.append(fmt_ratio(t / tp) if tp else "-")
            out.append("| " + " | ".join(row) + " |")
    out.append("")

    out.append(bar(medians))
    out.append(every_operation(medians, errors, label))
    out.append(growth(medians, counters))
    out.append(issue14_bars(medians, counters))

    out.append("Relative area difference against mkbool's exact area "
               f"(reference kernel `{context.get('mkbool_reference_kernel', '?')}`), "
               f"{TABLE_OP}:\n")
    runners = [p for p, _ in PEERS] + kernels
    header = ["workload"] + [label(r) for r in runners]
    out.append("| " + " | ".join(header) + " |")
    out.append("|" + "---|" * len(header))
    for w, n in TABLE_ROWS:
        row = [f"{w}, n = {fmt_n(n)}"]
        for r in runners:
            c = counters.get((r, w, TABLE_OP, n), {})
            d = c.get("area_rel_diff")
            row.append("-" if d is None else ("0" if d == 0 else f"{d:.1e}"))
        out.append("| " + " | ".join(row) + " |")
    out.append("")

    out.append("Largest relative area difference against the exact area over all cases of the run "
               "(every workload, operation and size with an exact reference):\n")
    out.append("| runner | max abs(area_rel_diff) | case |")
    out.append("|---|---|---|")
    for r in runners:
        worst = None
        for (rr, w, op, n), c in counters.items():
            d = c.get("area_rel_diff")
            if rr == r and d is not None and (worst is None or abs(d) > abs(worst[0])):
                worst = (d, f"{w}/{op}/{n}")
        if worst:
            out.append(f"| {label(r)} | {abs(worst[0]):.1e} | {worst[1] if worst[0] else '-'} |")
    out.append("")

    out.append(SUMMARY_END)
    out.append("## All runs\n")
    out.append("Median wall time; n is vertices per polygon (blob, star), squares per grid "
               "(checkerboard) or annuli per polygon (nested_squares, nested_wavy_rings).\n")
    all_runners = [p for p, _ in PEERS] + kernels
    header = ["workload", "op", "n"] + [label(r) for r in all_runners]
    out.append("| " + " | ".join(header) + " |")
    out.append("|" + "---|" * len(header))
    cases = sorted({k[1:] for k in list(medians) + list(errors)},
                   key=lambda c: (WORKLOADS.index(c[0]) if c[0] in WORKLOADS else 99,
                                  c[2], ["intersection", "union", "difference", "xor"].index(c[1])
                                  if c[1] in ["intersection", "union", "difference", "xor"] else 9))
    for w, op, n in cases:
        row = [w, op, str(n)] + [cell(medians, errors, (r, w, op, n)) for r in all_runners]
        out.append("| " + " | ".join(row) + " |")
    out.append("")
    if errors:
        out.append("Errors reported by the runners:\n")
        for (r, w, op, n), msg in sorted(errors.items()):
            out.append(f"- `{r}` {w}/{op}/{n}: {msg}")
        out.append("")

    keys = ["date", "mkbool_commit", "host_name", "num_cpus", "mhz_per_cpu", "load_avg",
            "GEOS_version", "BoostGeometry_version", "Clipper_version", "ClipperPolyTree_version", "CgalEpeck_version",
            "mkbool_kernels", "mkbool_reference_kernel", "overlay_full"]
    out.append("Context: " + "; ".join(f"{k} = {context[k]}" for k in keys if k in context) + "\n")
    return "\n".join(out)


def bar(medians):
    """The bar of BRIEF §6 / issue 5 for the exact kernel, met or not, from this run."""
    k = "mkbool:exact"
    get = lambda r, w, n: medians.get((r, w, TABLE_OP, n))
    lines = ["The bar for `exact` (BRIEF §6), from this run:\n", "| criterion | measured | met |",
             "|---|---|---|"]

    def row(text, value, ok):
        lines.append(f"| {text} | {value} | {'-' if ok is None else ('yes' if ok else 'no')} |")

    te = get(k, "blob", 100_000)
    fast = [t for t in (get(p, "blob", 100_000) for p in INEXACT_FAST_PEERS) if t]
    if te and fast:
        r = te / min(fast)
        row("blob 1e5: within 1.5x of the fastest of GEOS and Boost.Geometry", f"{r:.2f}x", r <= 1.5)
    tc = get("CgalEpeck", "blob", 100_000)
    if te and tc:
        row("blob 1e5: at least 50x faster than CGAL Epeck", f"{tc / te:.1f}x faster", tc / te >= 50)
    ts = get(k, "star", 10_000)
    tcl = get("Clipper", "star", 10_000)
    if ts and tcl:
        row("star 1e4: faster than Clipper", f"{tcl / ts:.2f}x faster", ts < tcl)
    tcg = get("CgalEpeck", "star", 10_000)
    if ts and tcg:
        row("star 1e4: at least 2x faster than CGAL Epeck", f"{tcg / ts:.2f}x faster", tcg / ts >= 2)
    for w in WORKLOADS:
        if w == "star":  # k grows as n^2 there: the slope is against n + k, not n
            continue
        pts = sorted((n, t) for (r, ww, op, n), t in medians.items() if r == k and ww == w and op == TABLE_OP)
        if len(pts) >= 2:
            (n0, t0), (n1, t1) = pts[0], pts[-1]
            slope = math.log(t1 / t0) / math.log(n1 / n0)
            guide = math.log((n1 * math.log(n1)) / (n0 * math.log(n0))) / math.log(n1 / n0)
            row(f"{w} {fmt_n(n0)}..{fmt_n(n1)}: time grows near n log n (log-log slope at most 1.25; "
                f"n log n gives {guide:.2f})", f"slope {slope:.2f}", slope <= 1.25)
    return "\n".join(lines) + "\n"


def largest_sizes(medians):
    """Per workload, the largest n `exact` ran at, and the largest below it that is a power of 10."""
    out = {}
    for w in WORKLOADS:
        ns = sorted({n for (r, ww, op, n) in medians if r == "mkbool:exact" and ww == w})
        if ns:
            out[w] = ns
    return out


def every_operation(medians, errors, label):
    """Every operation at 10^4 and at each workload's largest size: exact against the peers."""
    lines = ["Every operation, `exact` against the peers (median wall time; ratio = exact's time / "
             "the peer's, below 1: mkbool is faster):\n"]
    header = ["workload", "n", "op"] + [label(p) for p in EVERY_OP_PEERS] + \
             ["mkbool `exact`", "exact / GEOS", "exact / Boost.Geometry", "exact / Clipper PolyTree"]
    lines.append("| " + " | ".join(header) + " |")
    lines.append("|" + "---|" * len(header))
    for w, ns in largest_sizes(medians).items():
        regular = [n for n in ns if n < 10_000_000]
        shown = sorted({n for n in regular if n == 10_000} | {regular[-1]})
        for n in shown:
            for op in OPERATIONS:
                te = medians.get(("mkbool:exact", w, op, n))
                if te is None:
                    continue
                row = [w, fmt_n(n), op] + [cell(medians, errors, (p, w, op, n)) for p in EVERY_OP_PEERS]
                row.append(fmt_ms(te))
                for p in ("GEOS", "BoostGeometry", "ClipperPolyTree"):
                    tp = medians.get((p, w, op, n))
                    row.append(fmt_ratio(te / tp) if tp else "-")
                lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines) + "\n"


def size_of(counters, w, op, n):
    """The size time is measured against: input vertices plus crossings (exact's counters)."""
    c = counters.get(("mkbool:exact", w, op, n), {})
    v = c.get("vertices_in")
    if v is None:
        return None
    return v + c.get("crossings", 0)


def exact_growth(medians, counters, w, op):
    """exact's points (n + k, time, n) from 10^3 vertices on, its log-log slope over them and
    its steepest step (slope, n from, n to); None with fewer than two points."""
    pts = sorted((size_of(counters, w, op, n), t, n) for (r, ww, oo, n), t in medians.items()
                 if r == "mkbool:exact" and ww == w and oo == op and (size_of(counters, w, op, n) or 0) >= 1000)
    if len(pts) < 2:
        return None
    slope = math.log(pts[-1][1] / pts[0][1]) / math.log(pts[-1][0] / pts[0][0])
    steepest = max((math.log(b[1] / a[1]) / math.log(b[0] / a[0]), a[2], b[2]) for a, b in zip(pts, pts[1:]))
    return pts, slope, steepest


def growth(medians, counters):
    """Log-log slope of exact's time against n + k per workload and operation."""
    lines = [f"Growth of `exact`'s time with the size (input vertices plus crossings, n + k), per "
             f"workload and operation: the log-log slope from the first size with at least 10^3 "
             f"vertices to the largest, and the steepest step between two sizes of the run (issue "
             f"14's bar: at most {SLOPE_BAR}; n log n gives about 1.1 over three decades):\n",
             "| workload | op | sizes (n + k) | slope | steepest step | GEOS's slope, same sizes |",
             "|---|---|---|---|---|---|"]
    for w in WORKLOADS:
        for op in OPERATIONS:
            g = exact_growth(medians, counters, w, op)
            if g is None:
                continue
            pts, slope, worst = g
            s0, s1 = pts[0][0], pts[-1][0]
            geos = [(s, medians.get(("GEOS", w, op, n))) for s, _, n in pts]
            geos = [(s, t) for s, t in geos if t]
            gslope = (f"{math.log(geos[-1][1] / geos[0][1]) / math.log(geos[-1][0] / geos[0][0]):.2f} "
                      f"({fmt_n(int(geos[0][0]))}..{fmt_n(int(geos[-1][0]))})") if len(geos) >= 2 else "-"
            lines.append(f"| {w} | {op} | {fmt_size(s0)}..{fmt_size(s1)} | {slope:.2f} | "
                         f"{worst[0]:.2f} (n = {fmt_n(worst[1])} to {fmt_n(worst[2])}) | {gslope} |")
    return "\n".join(lines) + "\n"


def fmt_size(s):
    return f"{s:.2g}".replace("e+0", "e").replace("e+", "e")


def issue14_bars(medians, counters):
    """Issue 14's bars that one run of the benchmark measures, met or not."""
    get = lambda r, w, op, n: medians.get((r, w, op, n))
    k = "mkbool:exact"
    lines = ["Issue 14's bars measured by this run (`exact`; the command end to end, the cold "
             "process, memory and threads are measured apart, README):\n",
             "| bar | case | measured | met |", "|---|---|---|---|"]

    def row(text, case, value, ok):
        lines.append(f"| {text} | {case} | {value} | {'yes' if ok else 'no'} |")

    for op in OPERATIONS:
        te, tg, tc = get(k, "stripes", op, 8_000), get("GEOS", "stripes", op, 8_000), get("Clipper", "stripes", op, 8_000)
        if te and tg:
            row("stripes 8,000: faster than GEOS", op, f"{tg / te:.1f}x faster", te < tg)
        if te and tc:
            row("stripes 8,000: within 3x of Clipper", op, f"{te / tc:.2f}x", te <= 3 * tc)
    for w in ("checkerboard", "checkerboard_shared", "checkerboard_offset"):
        for n in (10_000, 100_000):
            for op in ("intersection", "union"):
                te = get(k, w, op, n)
                if not te:
                    continue
                tg, tp = get("GEOS", w, op, n), get("ClipperPolyTree", w, op, n)
                case = f"{w} {fmt_n(n)} {op}"
                if tg:
                    row("checkerboards: at least 5x faster than GEOS", case, f"{tg / te:.1f}x faster", tg >= 5 * te)
                if tp:
                    row("checkerboards: within 2x of Clipper PolyTree", case, f"{te / tp:.2f}x", te <= 2 * tp)
                else:
                    lines.append(f"| checkerboards: within 2x of Clipper PolyTree | {case} | Clipper PolyTree not run "
                                 "(bench/README.md, Limits) | - |")
    for n in (100_000, 1_000_000):
        te = get(k, "blob", "intersection", n)
        fast = [(get(p, "blob", "intersection", n), p) for p in INEXACT_FAST_PEERS]
        fast = [f for f in fast if f[0]]
        if te and fast:
            t, p = min(fast)
            row("blob: at most 1.0x the faster of GEOS and Boost.Geometry", f"{fmt_n(n)} intersection",
                f"{te / t:.2f}x ({p})", te <= t)
    te, tc = get(k, "star", "intersection", 10_000), get("Clipper", "star", "intersection", 10_000)
    if te and tc:
        row("star 1e4: faster than Clipper", "intersection", f"{tc / te:.1f}x faster", te < tc)
    return "\n".join(lines) + "\n"


def top_summary(context, medians, counters, errors):
    """The README's speed summary: the intersection at the table's sizes, growth, issue 14's bars."""
    label = lambda r: dict(PEERS).get(r, r)
    parts = f" in {context['parts']} parts (bench/README.md, Results)" if context.get("parts") else ""
    out = [f"One run of the default benchmark{parts}, {context.get('date', '?')[:16].replace('T', ' ')} UTC, mkbool "
           f"{context.get('mkbool_commit', '?')}, load average "
           f"{', '.join(f'{x:.1f}' for x in context.get('load_avg', []))} (1, 5, 15 minutes) at its start; median wall time of "
           "the intersection, the whole result as users receive it (polygons with their holes); "
           "every case and operation: bench/README.md and bench/results/overlay.md.\n"]
    header = ["workload, n", "n + k"] + [label(p) for p in COMPACT_PEERS] + ["mkbool `exact`",
                                                                          "exact / fastest peer"]
    out.append("| " + " | ".join(header) + " |")
    out.append("|" + "---|" * len(header))
    for w, n in TABLE_ROWS:
        te = medians.get(("mkbool:exact", w, TABLE_OP, n))
        if te is None:
            continue
        size = size_of(counters, w, TABLE_OP, n)
        peers = [(medians[(p, w, TABLE_OP, n)], p) for p in COMPACT_PEERS if (p, w, TABLE_OP, n) in medians]
        best = f"{te / min(peers)[0]:.2f}x ({label(min(peers)[1])})" if peers else "-"
        row = [f"{w}, {fmt_n(n)}", fmt_size(size) if size else "-"]
        row += [cell(medians, errors, (p, w, TABLE_OP, n)) for p in COMPACT_PEERS]
        row += [fmt_ms(te), best]
        out.append("| " + " | ".join(row) + " |")
    out.append("")
    out.append("*not run*: left out by the default run's limits (bench/README.md, \"Limits of the default "
               "run\"): each is a size where that library takes minutes.\n")
    out.append(issue14_bars(medians, counters))
    out.append(growth_summary(medians, counters))
    return "\n".join(out)


def growth_summary(medians, counters):
    """Per workload, the largest of the four operations' slopes (the table in bench/README.md)."""
    lines = [f"Growth (issue 14's bar: log-log slope of time against n + k at most {SLOPE_BAR} from 10^3 "
             "to 10^6 vertices): per workload, `exact`'s slope over the run's sizes, the largest of "
             "its four operations, and the steepest step between two sizes:\n",
             "| workload | sizes (n + k) | slope, largest of the 4 operations | steepest step | met |",
             "|---|---|---|---|---|"]
    for w in WORKLOADS:
        worst, step, span = None, None, None
        for op in OPERATIONS:
            g = exact_growth(medians, counters, w, op)
            if g is None:
                continue
            pts, slope, (st, _, _) = g
            if worst is None or slope > worst[0]:
                worst = (slope, op)
                span = f"{fmt_size(pts[0][0])}..{fmt_size(pts[-1][0])}"
            if step is None or st > step[0]:
                step = (st, op)
        if worst:
            lines.append(f"| {w} | {span} | {worst[0]:.2f} ({worst[1]}) | {step[0]:.2f} ({step[1]}) | "
                         f"{'yes' if worst[0] <= SLOPE_BAR else 'no'} |")
    return "\n".join(lines) + "\n"


def plot(medians, errors, path):
    """One log-log panel of time against n per workload (TABLE_OP), every runner in each."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    shown = [w for w in WORKLOADS if any(ww == w and op == TABLE_OP for (_, ww, op, _) in medians)]
    if not shown:
        return
    cols = min(3, len(shown))
    rows = (len(shown) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(5.2 * cols, 4.0 * rows), squeeze=False)
    runners = [p for p, _ in PEERS] + kernels_of(medians, errors)
    styles = {"GEOS": "s-", "BoostGeometry": "D-", "Clipper": "^-", "ClipperPolyTree": "<-", "CgalEpeck": "v-"}
    for ax, w in zip(axes.flat, shown):
        for r in runners:
            pts = sorted((n, t) for (rr, ww, op, n), t in medians.items() if rr == r and ww == w and op == TABLE_OP)
            if not pts:
                continue
            label = dict(PEERS).get(r, r)
            style = styles.get(r, "o--" if r != "mkbool:exact" else "o-")
            width = 2.5 if r == "mkbool:exact" else 1.2
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], style, label=label, linewidth=width, markersize=4)
        # An n log n guide through the fastest time at the smallest n.
        ns = sorted({n for (r, ww, op, n) in medians if ww == w and op == TABLE_OP})
        if len(ns) > 1 and ns[0] > 1:
            t0 = min(t for (r, ww, op, n), t in medians.items() if ww == w and op == TABLE_OP and n == ns[0])
            guide = [t0 * (n * math.log(n)) / (ns[0] * math.log(ns[0])) for n in ns]
            ax.loglog(ns, guide, ":", color="gray", label="n log n")
        ax.set_xlabel("n (bench/README.md, Workloads)")
        ax.set_ylabel("median wall time (ms)")
        ax.set_title(f"{w}, {TABLE_OP}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    for ax in list(axes.flat)[len(shown):]:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("json", nargs="+", help="one run's JSON; several: the parts of one run, a later part "
                    "replacing every case of the workloads it holds (a run stopped and resumed)")
    ap.add_argument("--markdown", help="write the tables here (default: stdout)")
    ap.add_argument("--plot", help="write the plot of every workload (PNG) here")
    ap.add_argument("--readme", help="replace the results between the markers of this README")
    ap.add_argument("--top-readme", help="replace the speed summary between the markers of this README")
    a = ap.parse_args()
    context, medians, runs, counters, errors = load_parts(a.json)
    text = markdown(context, medians, runs, counters, errors)
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    if a.plot:
        plot(medians, errors, a.plot)
    if a.readme:
        update_readme(a.readme, text.split(SUMMARY_END)[0], context)
    if a.top_readme:
        replace_between(a.top_readme, TOP_BEGIN, TOP_END, top_summary(context, medians, counters, errors))


def update_readme(path, summary, context):
    with open(path) as f:
        doc = f.read()
    begin, end = doc.index(README_BEGIN) + len(README_BEGIN), doc.index(README_END)
    run = f"Run of {context.get('date', '?')[:16].replace('T', ' ')} UTC (mkbool " \
          f"{context.get('mkbool_commit', '?')}), load average " \
          f"{', '.join(f'{x:.1f}' for x in context.get('load_avg', []))} on {context.get('num_cpus', '?')} CPUs" \
          f"{'' if not context.get('parts') else ', in ' + str(context['parts']) + ' parts (see above)'}. " \
          "Every case: bench/results/overlay.md.\n\n![time against n, every workload](results/overlay.png)\n\n"
    with open(path, "w") as f:
        f.write(doc[:begin] + "\n" + run + summary.rstrip() + "\n" + doc[end:])



def replace_between(path, begin_marker, end_marker, text):
    with open(path) as f:
        doc = f.read()
    begin, end = doc.index(begin_marker) + len(begin_marker), doc.index(end_marker)
    with open(path, "w") as f:
        f.write(doc[:begin] + "\n" + text.rstrip() + "\n" + doc[end:])


if __name__ == "__main__":
    main()
