#!/usr/bin/env bash
# A sweep as a Slurm array job: one task per shard (`mkbool-experiment run --shard i/N`),
# then one merge job that joins the shards and writes the report. [BRIEF §5] (sweeps split
# into shards for any batch scheduler)
# Preconditions: a shared filesystem between the nodes; mkbool built (scripts/main_job.sh or
# cmake --build build) so that build/bin/mkbool-experiment exists on every node.
#
# Usage (on the login node):
#   experiments/slurm_sweep.sh OUT_DIR [SHARDS] [run options...]
#   e.g. experiments/slurm_sweep.sh /scratch/$USER/sweep 64 --full
# This submits an array of SHARDS tasks (default 32) and a merge job that starts when they
# all succeed; OUT_DIR/README.md is the report. sbatch options such as --partition or
# --time come from the environment (SBATCH_PARTITION, SBATCH_TIMELIMIT, ...).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin="$root/build/bin/mkbool-experiment"

if [ -n "${SLURM_ARRAY_TASK_ID:-}" ]; then
  # Inside one array task: this shard only, one worker per allocated core, no report.
  out=$1
  shards=$2
  shift 2
  exec "$bin" run --shard "${SLURM_ARRAY_TASK_ID}/${shards}" --jobs "${SLURM_CPUS_PER_TASK:-1}" --no-report \
    -o "$out" "$@"
fi

if [ $# -lt 1 ]; then
  echo "usage: $0 OUT_DIR [SHARDS] [mkbool-experiment run options...]" >&2
  exit 2
fi
out=$1
shards=${2:-32}
shift $(( $# >= 2 ? 2 : 1 ))
[ -x "$bin" ] || { echo "$0: $bin not built" >&2; exit 1; }
mkdir -p "$out/logs"
array_job=$(sbatch --parsable --job-name=mkbool-sweep --array="0-$((shards - 1))" --cpus-per-task=1 \
  --output="$out/logs/shard-%a.log" "$0" "$out" "$shards" "$@")
merge_job=$(sbatch --parsable --job-name=mkbool-merge --dependency="afterok:${array_job}" \
  --output="$out/logs/merge.log" --wrap="'$bin' merge '$out'")
echo "submitted array job $array_job ($shards shards) and merge job $merge_job; report: $out/README.md"
