#!/usr/bin/env bash
# A sweep on a Slurm cluster: one shard per task of a job array (docs/sweeps.md, "On a Slurm cluster").
#   sbatch --array=1-8 scripts/sweep-slurm.sh cases/sweep-grid.yaml out/sweep-grid 8
# Task K of the array 1-N runs `rollwear sweep SWEEP --shard K/N -o OUT/shard_K` on its CPUs: the array
# index is the shard's number and N, the shard count, is the last argument. Once every task has ended:
#   rollwear sweep --merge out/sweep-grid/shard_* -o out/sweep-grid
# A task that was killed (time limit, pre-emption, scancel) is submitted again by the same command with
# its index alone, and resumes where it stopped (its finished cases are not run again):
#   sbatch --array=3 scripts/sweep-slurm.sh cases/sweep-grid.yaml out/sweep-grid 8
# ROLLWEAR names the program (default: rollwear on the PATH the job inherits from sbatch).
#SBATCH --job-name=rollwear-sweep
#SBATCH --cpus-per-task=4
#SBATCH --time=02:00:00
#SBATCH --output=rollwear-sweep-%A_%a.log
set -euo pipefail
usage() { sed -n '2,10p' "$0" >&2; exit 2; }
(($# == 3)) || usage
sweep="$1"
out="$2"
n="$3"
[[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "sweep-slurm.sh: the shard count N must be a whole number >= 1, got '$n'" >&2; exit 2; }
: "${SLURM_ARRAY_TASK_ID:?run as a job array: sbatch --array=1-N $0 SWEEP OUT N}"
# the array index is the shard's number: not derived from the array's size, which is 1 when a single
# task is submitted again (--array=3)
k="$SLURM_ARRAY_TASK_ID"
if ((k < 1 || k > n)); then
  echo "sweep-slurm.sh: array task $k is not a shard of $n: the array's indices are the shards 1-$n (sbatch --array=1-$n)" >&2
  exit 2
fi
exec "${ROLLWEAR:-rollwear}" sweep "$sweep" --shard "$k/$n" -o "$out/shard_$k" -j "${SLURM_CPUS_PER_TASK:-1}" -q
