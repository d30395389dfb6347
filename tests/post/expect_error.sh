#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# usage: expect_error.sh REGEX COMMAND [ARGS...]
# Passes when COMMAND exits with a status in 1..125 (an error, not a signal or a sanitizer
# abort), its stderr starts with "ERROR: ", matches REGEX (extended), and carries no
# sanitizer report.
regex=$1
shift
err=$("$@" 2>&1 >/dev/null)
status=$?
printf '%s\n' "$err"
if [ "$status" -eq 0 ] || [ "$status" -gt 125 ]; then
  echo "expect_error: exit status $status, expected an error exit" >&2
  exit 1
fi
case "$err" in
  ERROR:*) ;;
  *) echo "expect_error: stderr does not start with 'ERROR: '" >&2; exit 1 ;;
esac
if printf '%s' "$err" | grep -q -e 'Sanitizer' -e 'runtime error:'; then
  echo "expect_error: sanitizer report" >&2
  exit 1
fi
if ! printf '%s' "$err" | grep -q -E -e "$regex"; then
  echo "expect_error: stderr does not match '$regex'" >&2
  exit 1
fi
exit 0
