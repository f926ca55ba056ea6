#!/usr/bin/env bash
# Builds bench_overlay in Release, runs the benchmark against peers with repetitions, and
# writes bench/results/overlay.json, overlay.md and overlay.png (and, on a full default run,
# the results in bench/README.md and the speed summary in README.md).
# [BRIEF §6]
# Preconditions: Debian packages of BRIEF §9 (cmake, ninja, libbenchmark-dev, libgeos-dev,
# libboost-dev, libpolyclipping-dev, libcgal-dev, python3-matplotlib).
#
# Usage: bench/run_overlay.sh [bench_overlay flags...], e.g.
#   bench/run_overlay.sh --benchmark_filter='/blob/intersection/'   # a subset
#   bench/run_overlay.sh --overlay_full                              # no size limits
# Environment: MK_BENCH_BUILD_DIR (default build-bench), MK_BENCH_REPETITIONS (default 3),
# MK_BENCH_RESULTS (default bench/results).
set -euo pipefail

bench_dir=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$bench_dir")
build=${MK_BENCH_BUILD_DIR:-$root/build-bench}
results=${MK_BENCH_RESULTS:-$bench_dir/results}
repetitions=${MK_BENCH_REPETITIONS:-3}

if grep -qs 'add_subdirectory(peers)' "$bench_dir/CMakeLists.txt"; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMK_BUILD_TESTS=OFF >/dev/null
else
  # bench/CMakeLists.txt does not add peers/ yet: build through a small wrapper project.
  wrapper=$build/wrapper-src
  mkdir -p "$wrapper"
  cat >"$wrapper/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.22)
project(mkbool_bench_overlay CXX)
set(CMAKE_CXX_STANDARD 20)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_RUNTIME_OUTPUT_DIRECTORY \${CMAKE_BINARY_DIR}/bin)
set(MK_BUILD_TESTS OFF CACHE BOOL "" FORCE)
set(MK_SKIP_PARTS "bench;cli;experiments" CACHE STRING "" FORCE)
add_subdirectory("$root" mkbool)
add_subdirectory("$bench_dir/peers" peers)
CMAKE
  cmake -S "$wrapper" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" --target bench_overlay

mkdir -p "$results"
# Which code was measured: the commit, and whether the library's sources had uncommitted
# changes (the report shows both).
commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
if [ -n "$(git -C "$root" status --porcelain -- core arithmetic predicates api 2>/dev/null)" ]; then
  commit="$commit+uncommitted"
fi
start=$(date +%s)
"$build/bin/bench_overlay" --benchmark_repetitions="$repetitions" --benchmark_display_aggregates_only=true \
  --benchmark_context=mkbool_commit="$commit" \
  --benchmark_out="$results/overlay.json" --benchmark_out_format=json "$@"
echo "bench_overlay took $(($(date +%s) - start)) s"
readme=()
if [ "$results" = "$bench_dir/results" ] && [ $# -eq 0 ]; then
  # only a full default run updates the READMEs (bench/README.md's results, README.md's summary)
  readme=(--readme "$bench_dir/README.md" --top-readme "$root/README.md")
fi
/usr/bin/python3 "$bench_dir/plot_overlay.py" "$results/overlay.json" \
  --markdown "$results/overlay.md" --plot "$results/overlay.png" "${readme[@]}"
echo "wrote $results/overlay.json, overlay.md, overlay.png"
