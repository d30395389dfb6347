#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""One run of the bearing deck for the figure scripts (plot_lubricated_defect.py,
plot_bearing3d.py): the deck into FOLDER with its log there, its signal.txt read back by column
name. A failed run stops the script, naming the command and the log."""
import os
import subprocess
import sys

import numpy as np

DECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "inputs", "bearing_6208",
                    "in.bearing")


def run(who, exe, folder, **var):
    os.makedirs(folder, exist_ok=True)
    cmd = [exe, "-in", DECK, "-log", os.path.join(folder, "log.txt"), "-screen", "none",
           "-var", "out", folder]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    if subprocess.run(cmd, cwd=folder).returncode != 0:
        sys.exit(f"{who}: {' '.join(cmd)} failed (see {folder}/log.txt)")
    path = os.path.join(folder, "signal.txt")
    names = open(path).readline().split()[1:]
    data = np.loadtxt(path)
    return {n: data[:, i] for i, n in enumerate(names)}
