#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Called by inputs/bearing_6208/in.bearing (through LIGGGHTS' shell command, on rank 0) to turn
# -var bearing NAME into a LIGGGHTS snippet OUT that the deck includes:
#   - NAME in the catalog: include the catalog file, and define catalog_X for each of its
#     variables X, so that the deck can tell whether -var overrides changed the geometry;
#   - NAME = custom: no file; every dimension comes from -var (the deck checks them);
#   - otherwise: an error that lists the known names.
# A catalog entry is a regular file of DIR whose name has no dot (doc/bearing_catalog.md).
#   sh select.sh DIR NAME OUT
dir=$1 name=$2 out=$3

known() {
  for f in "$dir"/*; do
    b=${f##*/}
    case $b in *.*) continue ;; esac
    [ -f "$f" ] && printf ' %s' "$b"
  done
}

fail() {  # a LIGGGHTS print of the message, then a command that stops the run with it
  {
    printf 'print "ERROR: %s"\n' "$1"
    printf 'bearing_not_in_catalog %s\n' "$name"
  } >"$out"
  exit 0
}

case $name in
  custom)
    {
      echo "# bearing custom: every dimension comes from -var (checked by the deck)"
      for v in Nb Db Dext Dinn Rcext Rcinn; do echo "variable catalog_$v index -1"; done
    } >"$out"
    exit 0 ;;
  "" | */* | *.*)
    fail "bearing '$name' is not a catalog name (no path, no dot). Known bearings in $dir:$(known), or custom" ;;
esac
[ -f "$dir/$name" ] ||
  fail "bearing '$name' is not in the catalog $dir. Known bearings:$(known); or -var bearing custom with -var Nb, Db, Dext, Dinn (and optionally Rcext, Rcinn)"
{
  echo "# bearing $name from the catalog $dir"
  echo "include $dir/$name"
  sed -n 's/^[[:space:]]*variable[[:space:]]\{1,\}\([A-Za-z0-9_]\{1,\}\)[[:space:]]\{1,\}index[[:space:]]\{1,\}\([^[:space:]#]\{1,\}\).*/variable catalog_\1 index \2/p' "$dir/$name"
} >"$out"
