#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Called by in.sweep and sweep_slurm.sh: `start` notes when the sweep began (kept across resumed
# runs); a case that ends is recorded in ROOT/finished.txt (one line per case, its last end:
# a case run again replaces its line) and the sweep's progress is printed; `summary` prints
# every case of ROOT/sweep_cases.csv that did not finish, by name.
#   sweep_progress.sh ROOT NCASES start
#   sweep_progress.sh ROOT NCASES CASE started|done|FAILED
#   sweep_progress.sh ROOT NCASES summary
# (`started`, silent, marks a case whose end is still to come: one that never ends, its
# partition stopped by an engine error, is named by the summary.)
# Partitions and array tasks end cases at the same time: the update and the count are made
# under an exclusive lock of ROOT/.finished.lock (flock), so the counts never pass the table
# and print in order.
root=$1; ncases=$2; case=$3; status=$4
if [ "$case" = start ]; then
  [ -f "$root/t0" ] || date +%s > "$root/t0"
  exit 0
fi
t0=$(cat "$root/t0" 2>/dev/null || date +%s)
(
  flock 9
  touch "$root/finished.txt"
  if [ "$case" = summary ]; then
    done_n=$(grep -c ' done$' "$root/finished.txt")
    failed=$(sed -n 's/ FAILED$//p' "$root/finished.txt" |
      awk 'BEGIN { ORS = "" } { if (NR > 1) print "; "; print }')
    failed_n=$(grep -c ' FAILED$' "$root/finished.txt")
    started=$(sed -n 's/ started$//p' "$root/finished.txt" |
      awk 'BEGIN { ORS = "" } { if (NR > 1) print "; "; print }')
    nf=$((ncases - done_n - failed_n))
    line="sweep: summary: $done_n of $ncases cases done, $failed_n FAILED${failed:+ ($failed)}"
    line="$line, $nf not finished${started:+ (started, not ended: $started)}"
    echo "$line, $(( $(date +%s) - t0 )) s elapsed"
    exit 0
  fi
  # the case's line replaced (the label holds no line break: cases.py refuses them)
  CASE=$case awk '{ s = $0; sub(/ [A-Za-z]+$/, "", s); if (s != ENVIRON["CASE"]) print }' \
    "$root/finished.txt" > "$root/finished.txt.tmp$$"
  echo "$case $status" >> "$root/finished.txt.tmp$$"
  mv "$root/finished.txt.tmp$$" "$root/finished.txt"
  [ "$status" = started ] && exit 0
  done_n=$(grep -c ' done$' "$root/finished.txt")
  echo "sweep: $done_n/$ncases cases done, $(( $(date +%s) - t0 )) s elapsed (last: $case $status)"
) 9>"$root/.finished.lock"
