#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Called by in.bearing with -var resume 1 (sweeps): is the case in OUT already finished with the
# same parameters? OUT/run.done.json is the run.json of the case when it finished; OUT/run.json
# was just written for this run (status running). Writes OUT/resume.lmp:
#   variable case_done equal 1   the same parameters (run.json, status and time reached left
#                                out): the run is skipped, run.json restored from run.done.json
#   variable case_done equal 0   not finished, or with other parameters (said): run it
#   sweep_case.sh OUT
out=$1
strip() { sed -e 's/, "time_reached": [^,}]*//' -e 's/, "status": "[a-z]*"//' "$1"; }
done_flag=0
if [ -f "$out/run.done.json" ]; then
  if [ "$(strip "$out/run.done.json")" = "$(strip "$out/run.json")" ]; then
    cp "$out/run.done.json" "$out/run.json"
    done_flag=1
    echo "sweep: case $out already finished with the same parameters: skipped"
  else
    echo "sweep: case $out finished before with other parameters: run again"
    rm -f "$out/run.done.json"
  fi
fi
echo "variable case_done equal $done_flag" > "$out/resume.lmp"
