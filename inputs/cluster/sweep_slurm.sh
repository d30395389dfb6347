#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The cases of inputs/bearing_6208/in.sweep as a Slurm job array: one job per case, each
# running the bearing deck on its own (MPI inside a job is fine: -n > 1 gives the same
# numbers). Submit from the repository root:
#   sbatch inputs/cluster/sweep_slurm.sh                  (then, when all are done:)
#   build/ohmdem-post collect --format csv --output out/sweep/collected.csv out/sweep/size_*
# A resubmitted array skips the cases finished with the same parameters (run.done.json), like the
# partition sweep.
#SBATCH --job-name=ohmdem-sweep
#SBATCH --array=0-3
#SBATCH --ntasks=1
#SBATCH --time=01:00:00
#SBATCH --output=out/sweep/slurm-%A_%a.out
set -euo pipefail
SIZES=(0.5 1.0 2.0 3.0)          # the same cases as in.sweep
ROOT=${ROOT:-out/sweep}
TEND=${TEND:-0.05}
size=${SIZES[$SLURM_ARRAY_TASK_ID]}
out="$ROOT/size_$size"
mkdir -p "$out"
# Resume: in.bearing skips the case when its run.done.json has the same parameters; an
# interrupted or failed run exits non-zero and stops here (set -e), before the done mark.
srun build/ohmdem -in inputs/bearing_6208/in.bearing -var out "$out" -var tend "$TEND" \
  -var defect inner -var size "$size" -var resume 1 -var here inputs/bearing_6208 \
  -log "$out/log.liggghts" -screen none
cp "$out/run.json" "$out/run.done.json"
echo "case size=$size done"
