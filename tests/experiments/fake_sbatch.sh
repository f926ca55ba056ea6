#!/usr/bin/env bash
# A stand-in for Slurm's sbatch, for tests/experiments/slurm_test.cpp: it does what slurmd
# does with a batch job, synchronously. The batch script (or --wrap's command) is copied into
# a spool directory of its own and run from there, as slurmd runs its copy, so a script that
# looks for files next to itself fails here as it would on a cluster; an array job runs every
# task concurrently with SLURM_ARRAY_TASK_ID and SLURM_CPUS_PER_TASK set. Prints a job id
# (--parsable). Exits non-zero when a task fails, where Slurm would fail the job (and never
# start an afterok dependent).
# Preconditions: $FAKE_SBATCH_SPOOL is a writable directory.
set -euo pipefail
array='' wrap='' cpus=1
while [ $# -gt 0 ]; do
  case $1 in
    --array=*) array=${1#--array=} ;;
    --wrap=*) wrap=${1#--wrap=} ;;
    --cpus-per-task=*) cpus=${1#--cpus-per-task=} ;;
    --parsable | --job-name=* | --output=* | --dependency=afterok:*) ;;
    --*) echo "fake sbatch: unexpected option $1" >&2; exit 1 ;;
    *) break ;;
  esac
  shift
done
job=$(( $(ls "$FAKE_SBATCH_SPOOL" | wc -l) + 1000 ))
spool="$FAKE_SBATCH_SPOOL/job$job"
mkdir -p "$spool"
if [ -n "$wrap" ]; then
  printf '#!/bin/sh\n%s\n' "$wrap" > "$spool/slurm_script"
else
  cp "$1" "$spool/slurm_script"
  shift
fi
chmod +x "$spool/slurm_script"
if [ -z "$array" ]; then
  "$spool/slurm_script" "$@" > "$spool/out.log" 2>&1 || { cat "$spool/out.log" >&2; exit 1; }
else
  pids=()
  for i in $(seq "${array%-*}" "${array#*-}"); do
    SLURM_ARRAY_TASK_ID=$i SLURM_CPUS_PER_TASK=$cpus "$spool/slurm_script" "$@" > "$spool/task$i.log" 2>&1 &
    pids+=($!)
  done
  for p in "${pids[@]}"; do wait "$p" || { cat "$spool"/task*.log >&2; exit 1; }; done
fi
echo "$job"
