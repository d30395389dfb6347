#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Called by in.sweep: `start` notes when the sweep began (kept across resumed runs); a case
# that ends is recorded in ROOT/finished.txt and the sweep's progress is printed.
#   sweep_progress.sh ROOT NCASES start
#   sweep_progress.sh ROOT NCASES CASE done|FAILED
root=$1; ncases=$2; case=$3; status=$4
if [ "$case" = start ]; then
  [ -f "$root/t0" ] || date +%s > "$root/t0"
  exit 0
fi
echo "$case $status" >> "$root/finished.txt"
t0=$(cat "$root/t0" 2>/dev/null || date +%s)
echo "sweep: $(grep -c ' done$' "$root/finished.txt")/$ncases cases done, $(( $(date +%s) - t0 )) s elapsed (last: $case $status)"
