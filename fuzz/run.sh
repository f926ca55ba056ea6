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
# MK_FUZZ_TARGETS="fuzz_wkt ..." runs a subset; CXX_FUZZ overrides clang++.
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
flags=(-std=c++20 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
       -fno-omit-frame-pointer -ffp-contract=off -frounding-math -I "$root")
libs=(-lgmpxx -lgmp -lmpfr)

declare -A sources=(
  [fuzz_wkt]="io/wkt_reader.cpp io/wkt_writer.cpp io/format.cpp io/geojson_reader.cpp io/geojson_writer.cpp io/native_json.cpp io/parts.cpp io/ring_rules.cpp"
  [fuzz_geojson]="io/geojson_reader.cpp io/geojson_writer.cpp io/format.cpp io/wkt_reader.cpp io/native_json.cpp io/parts.cpp io/ring_rules.cpp"
  [fuzz_native_json]="io/native_json.cpp io/ring_rules.cpp"
  [fuzz_wkb]="io/wkb_reader.cpp io/wkb_writer.cpp io/ring_rules.cpp"
  [fuzz_operation]="api/mkbool.cpp api/fill.cpp io/wkt_writer.cpp io/geojson_writer.cpp io/native_json.cpp io/svg.cpp io/ring_rules.cpp"
)

failed=()
for target in ${MK_FUZZ_TARGETS:-fuzz_wkt fuzz_geojson fuzz_native_json fuzz_wkb fuzz_operation}; do
  echo "== building $target"
  files=("$root/fuzz/$target.cpp")
  for s in ${sources[$target]}; do files+=("$root/$s"); done
  "$cxx" "${flags[@]}" "${files[@]}" "${libs[@]}" -o "$work/$target"

  echo "== running $target for ${seconds}s"
  # New inputs go to a scratch corpus; the seeds in the repository are only read.
  mkdir -p "$work/corpus_$target"
  if [ "$target" = fuzz_operation ] && [ -x "$root/build/bin/fuzz_seed_corpus" ]; then
    "$root/build/bin/fuzz_seed_corpus" "$work/corpus_$target"
  fi
  if ! "$work/$target" -max_len=4096 -max_total_time="$seconds" -timeout=10 \
       -artifact_prefix="$artifacts/$target-" -print_final_stats=1 \
       "$work/corpus_$target" "$root/fuzz/corpus/$target" 2>"$work/$target.log"; then
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
