#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The cases of a case table (doc/case_table.md) as a Slurm job array: array task k runs the
# cases k*K .. k*K+K-1 (0-based rows of the table) one after the other, each with the bearing
# deck on its own (the cases are serial and short: K of them per task saves scheduling). Run
# from the repository root:
#   inputs/cluster/cases.py grid F=100,200 size=0.5,1,2 --output cases.csv
#   bash inputs/cluster/sweep_slurm.sh --submit cases.csv 2     (sbatch with --array=0-2)
#   build/ohmdem-post collect --format csv --output out/sweep/collected.csv out/sweep
# which is
#   sbatch --array=0-$((TASKS-1)) inputs/cluster/sweep_slurm.sh cases.csv 2
# with TASKS from `bash inputs/cluster/sweep_slurm.sh --tasks cases.csv 2`. One task by hand,
# without Slurm:
#   SLURM_ARRAY_TASK_ID=1 bash inputs/cluster/sweep_slurm.sh cases.csv 2
# Without a table the cases are the inner-defect sizes 0.5 1.0 2.0 3.0 (SIZES), K = 1: plain
# `sbatch inputs/cluster/sweep_slurm.sh` runs them as the array 0-3 below. Every deck variable
# not in the table comes from in.bearing, except tend (TEND, default 0.05) and defect (DEFECT,
# default inner), as in in.sweep; a column wins. The case folders are ROOT/NAME_VALUE... (ROOT
# default out/sweep), listed in ROOT/sweep_cases.csv. A resubmitted array skips the cases
# finished with the same parameters (run.done.json), like the partition sweep; a case that
# fails is said, the task goes on with its other cases and exits non-zero.
#SBATCH --job-name=ohmdem-sweep
#SBATCH --array=0-3
#SBATCH --ntasks=1
#SBATCH --time=01:00:00
#SBATCH --output=out/sweep/slurm-%A_%a.out
set -euo pipefail
# Under sbatch the script runs from a spool copy: the repository is the submission folder.
REPO=${SLURM_SUBMIT_DIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
CASES_PY="/usr/bin/python3 $REPO/inputs/cluster/cases.py"
DECK=$REPO/inputs/bearing_6208
OHMDEM=${OHMDEM:-$REPO/build/ohmdem}
ROOT=${ROOT:-out/sweep}
TEND=${TEND:-0.05}
DEFECT=${DEFECT:-inner}
SIZES=${SIZES:-0.5 1.0 2.0 3.0}
export OHMDEM_CATALOG=${OHMDEM_CATALOG:-$REPO/inputs/bearings}

fail() { echo "ERROR: sweep_slurm.sh: $*" >&2; exit 2; }

mode=run
case ${1:-} in
  --submit) mode=submit; shift ;;
  --tasks) mode=tasks; shift ;;
  -h|--help) sed -n '2,21p' "$0"; exit 0 ;;
  -*) fail "unknown option '$1' (expected --submit, --tasks, or CASES.csv [K])" ;;
esac
[ $# -le 2 ] || fail "too many arguments: expected [CASES.csv [K]], got $*"
mkdir -p "$ROOT"
if [ $# -ge 1 ]; then
  TABLE=$1
else  # the sizes as a one-column table
  TABLE=$ROOT/sizes.csv
  # shellcheck disable=SC2086
  $CASES_PY grid "size=$(echo $SIZES | tr ' ' ',')" --output "$TABLE"
fi
K=${2:-1}
# K reaches bash arithmetic below, which would run a $(...) inside an array index: digits only.
[[ $K =~ ^[1-9][0-9]*$ ]] || fail "K (cases per task) must be a whole number >= 1, got '$K'"
ncases=$($CASES_PY check "$TABLE" --deck "$DECK/in.bearing" --catalog "$OHMDEM_CATALOG")
ntasks=$($CASES_PY tasks "$TABLE" "$K")

case $mode in
  tasks) echo "$ntasks"; exit 0 ;;
  submit)
    set -x
    exec sbatch --array=0-$((ntasks - 1)) "$0" "$TABLE" "$K" ;;
esac

task=${SLURM_ARRAY_TASK_ID:-}
[ -n "$task" ] || fail "SLURM_ARRAY_TASK_ID is not set: submit with --submit $TABLE $K, or run one task by hand with SLURM_ARRAY_TASK_ID=k (0..$((ntasks - 1)))"
if ! [[ $task =~ ^[0-9]+$ ]] || [ "$task" -ge "$ntasks" ]; then
  fail "task index SLURM_ARRAY_TASK_ID=$task out of range: $TABLE has $ncases cases, $K per task: tasks 0..$((ntasks - 1))"
fi

# ROOT/sweep_cases.csv: the cases and their folders (every task writes the same file).
$CASES_PY sweep-table "$TABLE" "$ROOT"
launcher=()
if [ -n "${SLURM_JOB_ID:-}" ] && command -v srun >/dev/null; then launcher=(srun --ntasks=1); fi

sh "$DECK/sweep_progress.sh" "$ROOT" "$ncases" start
failed=0
first=$((task * K))
for ((i = first; i < first + K && i < ncases; i++)); do
  mapfile -t spec < <($CASES_PY args "$TABLE" "$i")
  folder=${spec[0]} label=${spec[1]}
  vars=()  # the row's, then TEND and DEFECT for what the row does not give (each -var once)
  given=" "
  for line in "${spec[@]:2}"; do
    vars+=(-var "${line%% *}" "${line#* }")
    given+="${line%% *} "
  done
  [[ $given == *" tend "* ]] || vars+=(-var tend "$TEND")
  [[ $given == *" defect "* ]] || vars+=(-var defect "$DEFECT")
  out=$ROOT/$folder
  mkdir -p "$out"
  # Resume: in.bearing skips the case when its run.done.json has the same parameters; a run
  # that does not finish exits non-zero and gets no done mark.
  if "${launcher[@]}" "$OHMDEM" -in "$DECK/in.bearing" "${vars[@]}" -var out "$out" \
      -var resume 1 -var here "$DECK" -log "$out/log.liggghts" -screen none; then
    cp "$out/run.json" "$out/run.done.json"
    sh "$DECK/sweep_progress.sh" "$ROOT" "$ncases" "$label" "done"
  else
    failed=$((failed + 1))
    echo "sweep: case $label FAILED (see $out/log.liggghts)" >&2
    sh "$DECK/sweep_progress.sh" "$ROOT" "$ncases" "$label" FAILED
  fi
done
sh "$DECK/sweep_progress.sh" "$ROOT" "$ncases" summary
[ "$failed" -eq 0 ] || fail "task $task: $failed of its cases failed"
