#!/usr/bin/env bash
# Runs a many-shape manifest across a Slurm job array: task K of COUNT takes the manifest's items
# whose 0-based index % COUNT == K (sdfwb --batch run --rank K --world-size COUNT), each in a
# child process with a time limit, recorded in its own status file. Resubmitting the array after
# a node failure or a time limit skips the items a task already finished.
#
#   sbatch --array=0-15 docs/examples/slurm_manifest.sh          # 16 tasks
#
# It also runs outside Slurm: SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT are then read from
# the environment (the test suite does that, running every task on one machine).
#SBATCH --job-name=sdfwb-manifest
#SBATCH --cpus-per-task=2
#SBATCH --mem=4G
#SBATCH --time=04:00:00
#SBATCH --output=sdfwb-manifest-%A_%a.log
set -euo pipefail

SDFWB=${SDFWB:-sdfwb}
MANIFEST=${MANIFEST:-shapes.jsonl}
ITEM_TIMEOUT=${ITEM_TIMEOUT:-1800}

task=${SLURM_ARRAY_TASK_ID:?run as a Slurm array job, or set SLURM_ARRAY_TASK_ID}
count=${SLURM_ARRAY_TASK_COUNT:?set SLURM_ARRAY_TASK_COUNT}
# Exit 1 means some items failed (recorded with their errors in the status file); the others ran.
exec "$SDFWB" --batch run "$MANIFEST" --rank "$task" --world-size "$count" --item-timeout "$ITEM_TIMEOUT"
