#!/usr/bin/env bash
# A sweep on a Slurm cluster: one shard per task of a job array (docs/sweeps.md, "On a cluster").
#   sbatch --array=1-8 scripts/sweep-slurm.sh cases/sweep-grid.yaml out/sweep-grid
# Task K of the N tasks runs `rollwear sweep SWEEP --shard K/N -o OUT/shard_K` on its CPUs. Once every
# task has ended, join the shards into the table the whole sweep gives:
#   rollwear sweep --merge out/sweep-grid/shard_* -o out/sweep-grid
# A task that was killed (time limit, pre-emption) resumes where it stopped when it is run again
# (sbatch --array=K ...): its finished cases are not run again.
# ROLLWEAR names the program (default: rollwear on the PATH).
#SBATCH --job-name=rollwear-sweep
#SBATCH --cpus-per-task=4
#SBATCH --time=02:00:00
#SBATCH --output=rollwear-sweep-%A_%a.log
set -euo pipefail
(($# == 2)) || { sed -n '2,10p' "$0" >&2; exit 2; }
sweep="$1"
out="$2"
: "${SLURM_ARRAY_TASK_ID:?run as a job array: sbatch --array=1-N $0 SWEEP OUT}"
: "${SLURM_ARRAY_TASK_COUNT:?run as a job array: sbatch --array=1-N $0 SWEEP OUT}"
k=$((SLURM_ARRAY_TASK_ID - ${SLURM_ARRAY_TASK_MIN:-1} + 1))  # 1..N whatever the array's first index
exec "${ROLLWEAR:-rollwear}" sweep "$sweep" --shard "$k/$SLURM_ARRAY_TASK_COUNT" -o "$out/shard_$k" \
  -j "${SLURM_CPUS_PER_TASK:-1}" -q
