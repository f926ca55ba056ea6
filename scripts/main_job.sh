#!/bin/sh
# The project's main job: build everything in Release and run the default robustness sweep
# of every kernel and peer library (GEOS, Boost.Geometry, Clipper, CGAL; peers on a sample of
# the generated cases and on every reported case) against the exact result, with a small
# union_all / intersection_all run of the set generators (72 cases); the report is
# report/README.md.
# [MK89 §3.3] See experiments/README.md for the sweep levels, the CSV schema and verdicts.
# Preconditions: run from anywhere inside the repository; Debian 12 packages of BRIEF.md §9
# (CMake, Ninja, GMP, Boost, CGAL, CLI11, GoogleTest, python3-matplotlib) installed.
# Extra arguments go to `mkbool-experiment run` (e.g. --quick, --full, --jobs 1).
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build

# The report directory is output only (never committed): start it afresh so that no
# stale CSV of an earlier sweep is counted in the report.
rm -rf report
start=$(date +%s)
build/bin/mkbool-experiment run "$@" -o report
end=$(date +%s)

echo
echo "sweep finished in $((end - start)) s"
echo "report: $root/report/README.md"
