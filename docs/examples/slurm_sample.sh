#!/usr/bin/env bash
# Samples one SDF across a cluster with a Slurm job array: task K of COUNT writes slice K of the
# N-sample run (sdfwb --batch sample --shard K/COUNT). After the array finishes, one merge job
# joins the slices into exactly the file a single run would have written.
#
#   sbatch --array=0-15 docs/examples/slurm_sample.sh          # 16 shards
#   sbatch --dependency=afterok:<array job id> --wrap "sdfwb --batch merge --output torus.npz shards/torus-*.npz"
#
# It also runs outside Slurm: SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT are then read from
# the environment (the test suite does that, running every task on one machine).
#SBATCH --job-name=sdfwb-sample
#SBATCH --cpus-per-task=2
#SBATCH --mem=2G
#SBATCH --time=01:00:00
#SBATCH --output=shards/%x-%A_%a.log
set -euo pipefail

SDFWB=${SDFWB:-sdfwb}
SDF=${SDF:-torus}
PATTERN=${PATTERN:-near}
N=${N:-100000000}
SEED=${SEED:-0}
OUT=${OUT:-shards}

task=${SLURM_ARRAY_TASK_ID:?run as a Slurm array job, or set SLURM_ARRAY_TASK_ID}
count=${SLURM_ARRAY_TASK_COUNT:?set SLURM_ARRAY_TASK_COUNT}
mkdir -p "$OUT"
# Zero-padded names sort in shard order; merge orders .npz/.ply shards by their metadata anyway.
printf -v part "%s/%s-%05d.npz" "$OUT" "$SDF" "$task"
exec "$SDFWB" --batch sample --sdf "$SDF" --pattern "$PATTERN" -n "$N" --seed "$SEED" \
     --shard "$task/$count" --output "$part" --quiet
