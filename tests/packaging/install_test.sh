#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# cmake --install gives a working tree: install BUILD into a temporary prefix, then run the
# bearing deck from there (a short run: from its own folder, the data folder and anywhere with
# no environment variable, and with OHMDEM_CATALOG), the post tool on its signal and a study
# command (studies/runup.py), away from the source tree.
#   install_test.sh BUILD_DIR WORK_DIR
set -eu
build=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >"$work/install.log"
share=$prefix/share/ohmdem/inputs
for f in bin/ohmdem bin/ohmdem-post \
         share/ohmdem/inputs/bearing_6208/sweep_case.sh share/ohmdem/inputs/bearings/6208 \
         share/ohmdem/inputs/bearing_6208/in.bearing share/doc/ohmdem/LICENSE \
         share/doc/ohmdem/CITATION.cff share/doc/ohmdem/README.md \
         share/doc/ohmdem/fix_bearing_race.md share/doc/ohmdem/ohmdem-post.md; do
  [ -e "$prefix/$f" ] || { echo "ERROR: $f not installed"; exit 1; }
done
for f in bearing_6208/sweep_case.sh bearing_6208/sweep_progress.sh; do
  [ -x "$share/$f" ] || { echo "ERROR: $f installed without its execute bit"; exit 1; }
done

finished() {  # finished DIR: the run wrote rows to signal.txt and ended with status finished
  rows=$(grep -vc '^#' "$1/signal.txt" || true)
  [ "$rows" -gt 0 ] || { echo "ERROR: $1/signal.txt has no rows"; exit 1; }
  grep -q '"status": "finished"' "$1/run.json" || { echo "ERROR: $1/run.json not finished"; exit 1; }
  echo "$1: $rows rows, finished"
}
short="-var tend 2e-4 -var dt 1e-5 -screen none"

# 1. with no OHMDEM_CATALOG (the deck's command bearing_catalog finds the catalog installed
#    beside the executable): from the deck's own folder, from the installed data folder and
#    from anywhere; the three runs are the same run
(cd "$share/bearing_6208" && env -u OHMDEM_CATALOG "$prefix/bin/ohmdem" -in in.bearing \
  -var out "$work/run_own" -log "$work/run_own.log" $short)
finished "$work/run_own"
(cd "$prefix/share/ohmdem" &&
  env -u OHMDEM_CATALOG "$prefix/bin/ohmdem" -in inputs/bearing_6208/in.bearing \
    -var out "$work/run_share" -log "$work/run_share.log" $short)
finished "$work/run_share"
cd "$work"
env -u OHMDEM_CATALOG "$prefix/bin/ohmdem" -in "$share/bearing_6208/in.bearing" -var out run_any \
  -log run_any.log $short
finished run_any
for f in signal.txt run.json; do
  cmp -s "$work/run_own/$f" "$work/run_share/$f" && cmp -s "$work/run_own/$f" run_any/$f ||
    { echo "ERROR: $f differs between the three places"; exit 1; }
done
grep -q "bearing_catalog: bearing machado2014 from $(realpath "$share/bearings")/machado2014" run_any.log ||
  { echo "ERROR: the installed ohmdem did not read the installed catalog"; exit 1; }

# 2. from anywhere, the catalog named by OHMDEM_CATALOG; a sweep case (resume 1) calls the
#    installed sweep_case.sh through -var here
OHMDEM_CATALOG=$share/bearings "$prefix/bin/ohmdem" -in "$share/bearing_6208/in.bearing" \
  -var out run_env -var here "$share/bearing_6208" -var resume 1 -log run_env.log $short
finished run_env
cp run_env/run.json run_env/run.done.json
OHMDEM_CATALOG=$share/bearings "$prefix/bin/ohmdem" -in "$share/bearing_6208/in.bearing" \
  -var out run_env -var here "$share/bearing_6208" -var resume 1 -log run_env2.log $short \
  >run_env2.out  # the script's message (LIGGGHTS' shell command) goes to standard output
grep -q "already finished with the same parameters: skipped" run_env2.out ||
  { echo "ERROR: the installed sweep_case.sh did not skip the finished case"; exit 1; }

# 3. the installed post tool reads the signal and finds the installed catalog by itself
env -u OHMDEM_CATALOG "$prefix/bin/ohmdem-post" stats run_env/signal.txt >post_stats.txt
env -u OHMDEM_CATALOG "$prefix/bin/ohmdem-post" frequencies --bearing 6205 --rpm 1797 >post_freq.txt
if env -u OHMDEM_CATALOG "$prefix/bin/ohmdem-post" frequencies --bearing nosuch --rpm 1 \
     2>post_err.txt; then
  echo "ERROR: an unknown bearing was accepted"; exit 1
fi
grep -q "catalog $(realpath "$share/bearings")" post_err.txt ||
  { echo "ERROR: the installed ohmdem-post does not read the installed catalog:"; cat post_err.txt; exit 1; }
# 4. a study command from the install, with no variable set: it finds PREFIX/bin/ohmdem,
#    PREFIX/bin/ohmdem-post and the installed decks and catalog by itself (the run-up study:
#    the quickest, one run of 0.35 s simulated)
studies=$prefix/share/ohmdem/studies
for f in common.py defects.py detectability.py load_speed.py runup.py locate_outer.py README.md; do
  [ -e "$studies/$f" ] || { echo "ERROR: studies/$f not installed"; exit 1; }
done
# the committed template bank locate_outer.py starts from, found through common.DOC in an install
/usr/bin/python3 -c "import os, sys; sys.path.insert(0, '$studies'); import common; \
sys.exit(0 if os.path.isfile(os.path.join(common.DOC, 'report', 'sizing', 'template', \
'bank_outer_radial_r20000_low.txt')) else 'ERROR: ' + common.DOC + ' holds no template bank')" || exit 1
settings=$(env -u OHMDEM -u POST -u OHMDEM_CATALOG /usr/bin/python3 "$studies/common.py" --shell)
for want in "OHMDEM=$prefix/bin/ohmdem" "POST=$prefix/bin/ohmdem-post" \
            "OHMDEM_CATALOG=$share/bearings"; do
  echo "$settings" | grep -qxF "export $want" ||
    { echo "ERROR: the installed studies do not use $want:"; echo "$settings"; exit 1; }
done
env -u OHMDEM -u POST -u OHMDEM_CATALOG /usr/bin/python3 "$studies/runup.py" study_runup \
  >study_runup.out 2>&1 || { echo "ERROR: the installed studies/runup.py failed:"; tail -5 study_runup.out; exit 1; }
grep -q 'reads \*\*inner\*\*' study_runup/runup.md ||
  { echo "ERROR: the installed run-up study did not identify the inner defect"; exit 1; }
finished study_runup
echo "install test: passed"
