#!/usr/bin/env python3
"""Writes aN.wkt and bN.wkt: two fans of N thin triangles each, every part touching the
others at the apex (0, 0), B turned by 0.3 of a step and of radius 90 against 100. A shape
outside the benchmark's workloads, where thousands of edges of both polygons meet at one
vertex (README, "no cliff where thousands of edges meet at one vertex").

Usage: bench/fan_wkt.py N [DIR]
"""
import math
import os
import sys


def fan(n, turn, radius):
    parts = []
    for i in range(n):
        a0 = 2 * math.pi * (i + turn) / n
        a1 = 2 * math.pi * (i + turn + 0.6) / n
        ring = [(0.0, 0.0), (radius * math.cos(a0), radius * math.sin(a0)),
                (radius * math.cos(a1), radius * math.sin(a1)), (0.0, 0.0)]
        parts.append("((%s))" % ", ".join("%r %r" % p for p in ring))
    return "MULTIPOLYGON(%s)\n" % ", ".join(parts)


def main():
    if len(sys.argv) not in (2, 3) or not sys.argv[1].isdigit() or int(sys.argv[1]) < 1:
        sys.exit("usage: fan_wkt.py N [DIR]  (N triangles per polygon, N >= 1)")
    n = int(sys.argv[1])
    out = sys.argv[2] if len(sys.argv) == 3 else "."
    with open(os.path.join(out, "a%d.wkt" % n), "w") as f:
        f.write(fan(n, 0.0, 100.0))
    with open(os.path.join(out, "b%d.wkt" % n), "w") as f:
        f.write(fan(n, 0.3, 90.0))


if __name__ == "__main__":
    main()
