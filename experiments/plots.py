# Plots of a robustness sweep from DIR/results*.csv: failure rate against perturbation size
# (ulp_perturbed), time against input size (blob, star), verdict maps of the kettner_grid
# cases, and failure rates of every back end per generator; rates carry 95% Wilson bars. [MK89 §3.3] [KMPSY08 §4]
# Preconditions: run with Debian's /usr/bin/python3 and python3-matplotlib; DIR is a sweep
# output directory. Writes DIR/plots/*.png; prints nothing on success.
import csv
import glob
import os
import statistics
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402

VERDICTS = ["exact_match", "valid_different", "invalid_output", "error", "timeout", "crash"]
COLOURS = ["#2e7d32", "#f9a825", "#c62828", "#6a1b9a", "#37474f", "#000000"]


def read_rows(directory):
    rows = []
    for path in sorted(glob.glob(os.path.join(directory, "results*.csv"))):
        with open(path, newline="") as f:
            rows.extend(csv.DictReader(f))
    return rows


def kernels_of(rows):
    seen = []
    for r in rows:
        if r["kernel"] != "reference" and r["kernel"] not in seen:
            seen.append(r["kernel"])
    return seen


def params(text):
    out = {}
    for item in filter(None, text.split(";")):
        name, value = item.split("=")
        out[name] = int(value)
    return out


STYLES = [("o", "-"), ("s", "--"), ("^", "-."), ("v", ":"), ("D", "-"), ("x", "--"), ("*", "-."), ("P", ":")]


def is_wrong(r):
    """Wrong beyond the rounding of constructed points (as in the report's table)."""
    if r["verdict"] in ("invalid_output", "error", "timeout", "crash"):
        return True
    return r["verdict"] == "valid_different" and r["area_error"] != "" and float(r["area_error"]) > 1e-12


def wilson(k, n, z=1.959963984540054):
    """95% Wilson score interval of k in n, as (low, high) fractions (statistics.hpp)."""
    if n == 0:
        return 0.0, 1.0
    p = k / n
    denom = 1 + z * z / n
    centre = (p + z * z / (2 * n)) / denom
    half = z * ((p * (1 - p) / n + z * z / (4 * n * n)) ** 0.5) / denom
    return (0.0 if k == 0 else max(0.0, centre - half)), (1.0 if k == n else min(1.0, centre + half))


def error_bars(ks, ns):
    """Asymmetric error bars (in %) of the rates k/n."""
    lows, highs = [], []
    for k, n in zip(ks, ns):
        lo, hi = wilson(k, n)
        lows.append(100.0 * (k / n - lo))
        highs.append(100.0 * (hi - k / n))
    return [lows, highs]


def fails(r):
    """A failed run on the report's one scale for kernels and peers (report_library.cpp)."""
    v = r["verdict"]
    if v in ("wrong", "invalid_output", "exception", "crash", "timeout"):
        return True
    if v == "error":
        return not r["message"].startswith("InvalidInput")
    if v == "valid_different" and r["symdiff_area"] != "" and r.get("rounding_bound", "") != "":
        return float(r["symdiff_area"]) > float(r["rounding_bound"])
    return False


def library_failures(rows, out):
    """Failure rate of every back end (kernels and peers) per generator, with Wilson bars."""
    runs = [r for r in rows if r["kernel"] != "reference"]
    if not any(r["kernel"] in ("geos", "boost", "clipper", "cgal_epeck") for r in runs):
        return
    backends, generators = [], []
    for r in runs:
        if r["kernel"] not in backends:
            backends.append(r["kernel"])
        if r["generator"] not in generators:
            generators.append(r["generator"])
    counts = defaultdict(lambda: [0, 0])
    for r in runs:
        c = counts[(r["generator"], r["kernel"])]
        c[1] += 1
        c[0] += 1 if fails(r) else 0
    # Small multiples: one panel per generator, one bar per back end (same order and colour
    # in every panel), each with its 95% Wilson interval.
    cols = 4
    rows_n = (len(generators) + cols - 1) // cols
    fig, axes = plt.subplots(rows_n, cols, figsize=(3.4 * cols, 2.9 * rows_n), squeeze=False)
    cmap = plt.get_cmap("tab10")
    colours = [cmap(i % 10) for i in range(len(backends))]
    for index, gen in enumerate(generators):
        ax = axes[index // cols][index % cols]
        xs, rates, ks, ns, cs = [], [], [], [], []
        for b_index, backend in enumerate(backends):
            k, n = counts[(gen, backend)]
            if n == 0:
                continue
            xs.append(b_index)
            rates.append(100.0 * k / n)
            ks.append(k)
            ns.append(n)
            cs.append(colours[b_index])
        ax.bar(xs, rates, color=cs, yerr=error_bars(ks, ns), capsize=2, error_kw={"elinewidth": 0.8})
        ax.set_title(gen, fontsize=10)
        ax.set_xticks(range(len(backends)))
        ax.set_xticklabels(backends, rotation=60, ha="right", fontsize=7)
        ax.set_ylim(0, max(5.0, max((r + e for r, e in zip(rates, error_bars(ks, ns)[1])), default=0) * 1.1))
        ax.grid(axis="y", alpha=0.3)
        if index % cols == 0:
            ax.set_ylabel("failed runs (%)")
    for index in range(len(generators), rows_n * cols):
        axes[index // cols][index % cols].axis("off")
    fig.suptitle("Failed runs per generator and back end (wrong, invalid output, exception, crash, timeout); "
                 "bars: 95% Wilson intervals", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    fig.savefig(os.path.join(out, "library_failures.png"), dpi=110)
    plt.close(fig)


def failure_vs_ulps(rows, kernels, out):
    runs = [r for r in rows if r["generator"] == "ulp_perturbed" and r["kernel"] != "reference"]
    if not runs:
        return
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
    titles = ["any difference (not exact_match)", "wrong beyond rounding"]
    tests = [lambda r: r["verdict"] != "exact_match", is_wrong]
    for ax, title, bad in zip(axes, titles, tests):
        for n, kernel in enumerate(kernels):
            by_k = defaultdict(lambda: [0, 0])
            for r in runs:
                if r["kernel"] != kernel:
                    continue
                k = params(r["params"]).get("k", 0)
                by_k[k][1] += 1
                if bad(r):
                    by_k[k][0] += 1
            if not by_k:
                continue
            ks = sorted(by_k)
            marker, line = STYLES[n % len(STYLES)]
            # Kernels that decide alike overlap exactly: distinct markers and dashes keep
            # each visible; bars are 95% Wilson intervals.
            ax.errorbar(ks, [100.0 * by_k[k][0] / by_k[k][1] for k in ks],
                        yerr=error_bars([by_k[k][0] for k in ks], [by_k[k][1] for k in ks]), marker=marker,
                        linestyle=line, markersize=max(3, 9 - n), alpha=0.8, capsize=2, label=kernel)
        ax.set_title(title)
        ax.set_xlabel("k: ulps the vertex is moved off the edge (0: exactly on it)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("runs (%)")
    axes[0].legend()
    fig.suptitle("ulp_perturbed: failure rate against perturbation size")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "failure_vs_ulps.png"), dpi=110)
    plt.close(fig)


def time_vs_size(rows, kernels, out):
    gens = [g for g in ("blob", "star") if any(r["generator"] == g for r in rows)]
    if not gens:
        return
    fig, axes = plt.subplots(1, len(gens), figsize=(6 * len(gens), 4.5), squeeze=False)
    for ax, gen in zip(axes[0], gens):
        for n_kernel, kernel in enumerate(kernels):
            by_n = defaultdict(list)
            for r in rows:
                if (r["generator"] == gen and r["kernel"] == kernel and r["op"] == "intersection"
                        and r["regular"] == "true" and r["op_ns"]):
                    by_n[int(r["size"])].append(int(r["op_ns"]) * 1e-6)
            if not by_n:
                continue
            ns = sorted(by_n)
            marker, line = STYLES[n_kernel % len(STYLES)]
            ax.plot(ns, [statistics.median(by_n[n]) for n in ns], marker=marker, linestyle=line, label=kernel)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("input vertices (A and B)")
        ax.set_ylabel("median time of A ∩ B (ms)")
        ax.set_title(gen)
        ax.grid(alpha=0.3, which="both")
        ax.legend()
    fig.suptitle("Time against input size")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "time_vs_size.png"), dpi=110)
    plt.close(fig)


def kettner_maps(rows, kernels, out):
    runs = [r for r in rows if r["generator"] == "kettner_grid" and r["kernel"] != "reference"]
    if not runs:
        return
    variants = sorted({r["variant"] for r in runs})
    # The worst verdict over the operations of each grid point.
    worst = defaultdict(int)
    coords = set()
    for r in runs:
        p = params(r["params"])
        key = (r["kernel"], r["variant"], p["i"], p["j"])
        coords.add((p["i"], p["j"]))
        worst[key] = max(worst[key], VERDICTS.index(r["verdict"]) if r["verdict"] in VERDICTS else 0)
    xs = sorted({c[0] for c in coords})
    ys = sorted({c[1] for c in coords})
    fig, axes = plt.subplots(len(variants), len(kernels), figsize=(2.6 * len(kernels), 2.6 * len(variants)),
                             squeeze=False)
    cmap = ListedColormap(COLOURS)
    for vi, variant in enumerate(variants):
        for ki, kernel in enumerate(kernels):
            grid = [[worst.get((kernel, variant, x, y), 0) for x in xs] for y in ys]
            ax = axes[vi][ki]
            ax.imshow(grid, origin="lower", cmap=cmap, vmin=-0.5, vmax=len(VERDICTS) - 0.5, interpolation="nearest",
                      extent=(xs[0] - 0.5, xs[-1] + 0.5, ys[0] - 0.5, ys[-1] + 0.5))
            ax.set_xticks([])
            ax.set_yticks([])
            if vi == 0:
                ax.set_title(kernel)
            if ki == 0:
                ax.set_ylabel(variant)
    handles = [plt.Rectangle((0, 0), 1, 1, color=c) for c in COLOURS]
    fig.legend(handles, VERDICTS, loc="lower center", ncol=len(VERDICTS))
    fig.suptitle("kettner_grid: worst verdict over all operations at p + (i, j) ulps (i right, j up)")
    fig.tight_layout(rect=(0, 0.06, 1, 0.95))
    fig.savefig(os.path.join(out, "kettner_grid.png"), dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: plots.py DIR")
    directory = sys.argv[1]
    rows = read_rows(directory)
    out = os.path.join(directory, "plots")
    os.makedirs(out, exist_ok=True)
    kernels = kernels_of(rows)
    failure_vs_ulps(rows, kernels, out)
    time_vs_size(rows, kernels, out)
    kettner_maps(rows, kernels, out)
    library_failures(rows, out)


if __name__ == "__main__":
    main()
