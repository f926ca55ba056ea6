#!/usr/bin/env bash
# The command end to end against GEOS: wall time of `mkbool OP A.wkt B.wkt -o OUT.wkt` (a
# fresh process: read, check, operation, certified rounding, WKT written) and of
# build/bin/geos_command (GEOS: read, overlay, write with 17 digits), alternating, median
# of REPEATS each, on inputs written by overlay_phases --wkt. [BRIEF §6] (issue 17's bar:
# mkbool at most 1.5x GEOS on blob 1e6)
# Usage: bench/end_to_end.sh [WORKLOAD [N [OP [REPEATS]]]]   (default: blob 1000000 intersection 5)
# Environment: MK_BUILD_DIR (default build), MKBOOL_ARGS (extra mkbool options, e.g. "--threads 1").
# Preconditions: a build with bin/mkbool, bin/overlay_phases and bin/geos_command (GEOS found).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${MK_BUILD_DIR:-$root/build}/bin"
workload="${1:-blob}"; n="${2:-1000000}"; op="${3:-intersection}"; repeats="${4:-5}"
work="$(mktemp -d -t mkbool-e2e.XXXXXX)"
trap 'rm -rf "$work"' EXIT
"$bin/overlay_phases" --wkt "$workload" "$n" "$work/a.wkt" "$work/b.wkt"
seconds() { local t0 t1; t0=$(date +%s%N); "$@" >/dev/null 2>&1; t1=$(date +%s%N); echo "$(( (t1 - t0) / 1000000 ))"; }
median() { sort -n | awk '{v[NR]=$1} END {print v[int((NR + 1) / 2)]}'; }
mk=(); geos=()
for ((i = 0; i < repeats; i++)); do
  # shellcheck disable=SC2086
  mk+=("$(seconds "$bin/mkbool" "$op" "$work/a.wkt" "$work/b.wkt" ${MKBOOL_ARGS:-} -o "$work/mk.wkt")")
  geos+=("$(seconds "$bin/geos_command" "$op" "$work/a.wkt" "$work/b.wkt" "$work/geos.wkt")")
done
mk_med=$(printf '%s\n' "${mk[@]}" | median)
geos_med=$(printf '%s\n' "${geos[@]}" | median)
echo "$workload $n $op: input $(($(stat -c %s "$work/a.wkt") + $(stat -c %s "$work/b.wkt"))) bytes, output mkbool $(stat -c %s "$work/mk.wkt") GEOS $(stat -c %s "$work/geos.wkt") bytes"
echo "mkbool ${MKBOOL_ARGS:-} (ms): ${mk[*]}  median $mk_med"
echo "GEOS read+op+write (ms): ${geos[*]}  median $geos_med"
awk -v m="$mk_med" -v g="$geos_med" 'BEGIN { printf "mkbool / GEOS: %.2fx\n", m / g }'
