#!/usr/bin/env bash
# Builds the fuzz targets with libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer
# (clang++, outside the CMake build) and runs each for a number of seconds: the four input
# parsers, and the whole operation (fuzz_operation: two polygons from the bytes, every
# operation, exact and rational kernels agreeing exactly). When the CMake build has made
# build/bin/fuzz_seed_corpus, fuzz_operation's scratch corpus is first seeded with cases of
# the experiment generators; the committed seeds are a small selection of those.
# Usage: fuzz/run.sh [seconds per target, default 20]
# Exit status: 0 when no target crashed, leaked, hung or hit undefined behaviour; 1 otherwise.
# Crash inputs are kept in $MK_FUZZ_ARTIFACTS (default /tmp/mkbool-fuzz-artifacts);
# MK_FUZZ_TARGETS="fuzz_wkt ..." runs a subset; CXX_FUZZ overrides clang++; MK_FUZZ_JOBS
# sets how many compilations and targets run at once (default: one per core).
set -euo pipefail

seconds="${1:-20}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cxx="${CXX_FUZZ:-clang++}"
artifacts="${MK_FUZZ_ARTIFACTS:-/tmp/mkbool-fuzz-artifacts}"
work="$(mktemp -d -t mkbool-fuzz.XXXXXX)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$artifacts"

# -fno-sanitize-recover: undefined behaviour aborts, so libFuzzer reports it as a crash.
# -ffp-contract=off and -frounding-math as the CMake build gives the exact predicates.
# Every source is compiled once with coverage instrumentation (fuzzer-no-link), the sources
# on every core at once, largest first; each target is then linked with libFuzzer's main.
cflags=(-std=c++20 -g -O1 -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
        -fno-omit-frame-pointer -ffp-contract=off -frounding-math -I "$root")
lflags=(-fsanitize=fuzzer,address,undefined)
libs=(-lgmpxx -lgmp -lmpfr)
jobs="${MK_FUZZ_JOBS:-$(nproc)}"

declare -A sources=(
  [fuzz_wkt]="io/wkt_reader.cpp io/wkt_writer.cpp io/format.cpp io/geojson_reader.cpp io/geojson_writer.cpp io/native_json.cpp io/parts.cpp io/ring_rules.cpp"
  [fuzz_geojson]="io/geojson_reader.cpp io/geojson_writer.cpp io/format.cpp io/wkt_reader.cpp io/native_json.cpp io/parts.cpp io/ring_rules.cpp"
  [fuzz_native_json]="io/native_json.cpp io/ring_rules.cpp"
  [fuzz_wkb]="io/wkb_reader.cpp io/wkb_writer.cpp io/ring_rules.cpp"
  [fuzz_operation]="$work/api_unity.cpp io/wkt_writer.cpp io/geojson_writer.cpp io/native_json.cpp io/svg.cpp io/ring_rules.cpp"
)
read -r -a targets <<< "${MK_FUZZ_TARGETS:-fuzz_wkt fuzz_geojson fuzz_native_json fuzz_wkb fuzz_operation}"

object() { local u="${1#"$work"/}"; echo "$work/obj/${u//\//_}.o"; }
# A unit's source: a path under the repository, or an absolute one (a unit made here).
source_of() { if [[ "$1" == /* ]]; then echo "$1"; else echo "$root/$1"; fi; }

# Runs "$@" for each line of standard input as its last argument, at most $jobs at a time;
# fails when any run failed.
parallel_each() {
  local running=0 status=0 item
  while read -r item; do
    "$@" "$item" &
    running=$((running + 1))
    if ((running >= jobs)); then
      wait -n || status=1
      running=$((running - 1))
    fi
  done
  while ((running > 0)); do
    wait -n || status=1
    running=$((running - 1))
  done
  return "$status"
}

compile_unit() { "$cxx" "${cflags[@]}" -c "$(source_of "$1")" -o "$(object "$1")"; }

# The library's two files as one unit: they instantiate most of the same templates, and
# apart they took most of this script's compilation time.
printf '#include "api/mkbool.cpp"\n#include "api/fill.cpp"\n' > "$work/api_unity.cpp"

echo "== building ${targets[*]}"
mkdir -p "$work/obj"
units=()
for target in "${targets[@]}"; do
  units+=("fuzz/$target.cpp")
  for s in ${sources[$target]}; do units+=("$s"); done
done
# Largest first (by size; the made unit, the largest by far, before all).
unit_size() { if [[ "$1" == /* ]]; then echo 999999999; else stat -c %s "$root/$1"; fi; }
printf '%s\n' "${units[@]}" | sort -u | while read -r u; do echo "$(unit_size "$u") $u"; done \
  | sort -rn | cut -d' ' -f2 | parallel_each compile_unit
for target in "${targets[@]}"; do
  objects=("$(object "fuzz/$target.cpp")")
  for s in ${sources[$target]}; do objects+=("$(object "$s")"); done
  "$cxx" "${lflags[@]}" "${objects[@]}" "${libs[@]}" -o "$work/$target"
done

# Runs one target; its log and exit status are left in $work.
run_target() {
  local target="$1"
  # New inputs go to a scratch corpus; the seeds in the repository are only read.
  mkdir -p "$work/corpus_$target"
  if [ "$target" = fuzz_operation ] && [ -x "$root/build/bin/fuzz_seed_corpus" ]; then
    "$root/build/bin/fuzz_seed_corpus" "$work/corpus_$target" >/dev/null
  fi
  local rc=0
  "$work/$target" -max_len=4096 -max_total_time="$seconds" -timeout=10 \
    -artifact_prefix="$artifacts/$target-" -print_final_stats=1 \
    "$work/corpus_$target" "$root/fuzz/corpus/$target" 2>"$work/$target.log" || rc=$?
  echo "$rc" > "$work/$target.rc"
}

echo "== running each target for ${seconds}s, $jobs at a time"
printf '%s\n' "${targets[@]}" | parallel_each run_target || true
failed=()
for target in "${targets[@]}"; do
  echo "== $target"
  if [ "$(cat "$work/$target.rc" 2>/dev/null || echo 1)" != 0 ]; then
    tail -n 60 "$work/$target.log"
    failed+=("$target")
  else
    grep -E "^(stat::number_of_executed_units|Done)" "$work/$target.log" || true
  fi
done

if ((${#failed[@]} > 0)); then
  echo "FAILED: ${failed[*]} (inputs in $artifacts)"
  exit 1
fi
echo "all fuzz targets ran clean"
