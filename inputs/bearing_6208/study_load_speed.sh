#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The load and speed study (indicators and diagnosis of R against F and the inner speed,
# healthy and with a 1 deg inner defect, ring under force and held). Writes OUT/load_speed.md.
#   inputs/bearing_6208/study_load_speed.sh [--quick] OUT
set -euo pipefail
exec /usr/bin/python3 "$(dirname "$0")/study_load_speed.py" "$@"
