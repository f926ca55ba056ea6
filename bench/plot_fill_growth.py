#!/usr/bin/python3
# Growth of union-all with size (issue 13): from bench_fill's `spread` workload (32-gons at a
# constant density, 10^3 to 10^6 vertices in all), the log-log slope of time against the
# input's vertices n and against n + k (k: crossings, as mkbool counts them), per library,
# as a Markdown table and a log-log plot.
# [BRIEF §6] (growth near (n + k) log n)
# Preconditions: JSON written by bin/bench_fill --benchmark_filter='UnionAll<.*>/spread'
# --benchmark_out=FILE --benchmark_out_format=json (any --benchmark_repetitions); run with
# /usr/bin/python3 (matplotlib from python3-matplotlib).
"""Usage: plot_fill_growth.py fill.json [--plot fill_growth.png]"""

import argparse
import json
import math
import re
import statistics
from collections import defaultdict

NAME = re.compile(r"^BM_UnionAll<(?P<lib>\w+)>/spread/(?P<n>\d+)")
TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def slope(xs, ys):
    """Least-squares slope of log y against log x."""
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = statistics.mean(lx), statistics.mean(ly)
    den = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / den if den else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("json")
    ap.add_argument("--plot")
    args = ap.parse_args()
    with open(args.json) as f:
        doc = json.load(f)
    times = defaultdict(list)
    size = {}  # parts -> (vertices in, crossings) from mkbool's counters
    for b in doc["benchmarks"]:
        if b.get("run_type") == "aggregate" or b.get("error_occurred"):
            continue
        m = NAME.match(b.get("run_name", b["name"]))
        if not m:
            continue
        parts = int(m["n"])
        times[(m["lib"], parts)].append(b["real_time"] * TO_MS[b.get("time_unit", "ns")])
        if m["lib"] == "Mkbool":
            size[parts] = (int(b["vertices_in"]), int(b["crossings"]))
    libs = sorted({lib for lib, _ in times})
    all_parts = sorted(size)
    print("| parts | vertices n | crossings k | " + " | ".join(f"{lib} (ms)" for lib in libs) + " |")
    print("|---|---|---|" + "---|" * len(libs))
    for parts in all_parts:
        n, k = size[parts]
        cells = [f"{statistics.median(times[(lib, parts)]):.3g}" if (lib, parts) in times else "-" for lib in libs]
        print(f"| {parts:,} | {n:,} | {k:,} | " + " | ".join(cells) + " |")
    for lib in libs:
        ps = [p for p in all_parts if (lib, p) in times]
        if len(ps) < 2:
            continue
        ts = [statistics.median(times[(lib, p)]) for p in ps]
        print(f"{lib}: slope against n {slope([size[p][0] for p in ps], ts):.2f}, "
              f"against n + k {slope([size[p][0] + size[p][1] for p in ps], ts):.2f}")
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4))
        for lib in libs:
            ps = [p for p in all_parts if (lib, p) in times]
            ax.plot([size[p][0] for p in ps], [statistics.median(times[(lib, p)]) for p in ps], marker="o", label=lib)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("vertices in all (32-gons at constant density)")
        ax.set_ylabel("union-all, median ms")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(args.plot, dpi=100)


if __name__ == "__main__":
    main()
