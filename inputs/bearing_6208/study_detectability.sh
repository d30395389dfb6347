#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The detectability study: defect sizes x instruments (sampling rate, noise, ADC bits) x
# channels (electrical R, ring acceleration), acquired and diagnosed with ohmdem-post.
# Writes OUT/detectability.csv, OUT/detectability.md and the maps.
#   inputs/bearing_6208/study_detectability.sh [--quick] OUT
set -euo pipefail
exec /usr/bin/python3 "$(dirname "$0")/study_detectability.py" "$@"
