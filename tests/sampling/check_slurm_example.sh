#!/usr/bin/env bash
# Runs docs/examples/slurm_sample.sh as Slurm would (one process per array task, here in a row),
# merges the shards, and checks the result is byte-identical to a single run.
set -euo pipefail
sdfwb=$1 work=$2 script=$3
rm -rf "$work" && mkdir -p "$work"
export SDFWB=$sdfwb SDF=torus PATTERN=near N=30011 SEED=3 OUT=$work/shards
unset DISPLAY
for task in 0 1 2 3; do SLURM_ARRAY_TASK_ID=$task SLURM_ARRAY_TASK_COUNT=4 bash "$script"; done
"$sdfwb" --batch merge --output "$work/merged.npz" "$work"/shards/torus-*.npz --quiet
"$sdfwb" --batch sample --sdf torus --pattern near -n 30011 --seed 3 --output "$work/single.npz" --quiet
cmp "$work/merged.npz" "$work/single.npz"
echo "4 Slurm-style shards merged into the single run's file, byte for byte"
