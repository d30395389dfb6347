# SPDX-License-Identifier: GPL-2.0-or-later
"""Shared by the deck test drivers: report a check, remember failures, read signal.txt."""
import sys

import numpy as np

_failed = False


def check(cond, msg):
    """Prints 'ok' or 'FAIL' with the message; a failure makes finish() exit non-zero."""
    global _failed
    print(("ok   " if cond else "FAIL ") + msg)
    _failed |= not cond


def finish():
    if _failed:
        sys.exit(1)
    print("all checks passed")


def read_signal(path):
    """signal.txt as a dict of columns, named by its '#' header line."""
    with open(path) as f:
        names = f.readline().lstrip("#").split()
    data = np.loadtxt(path, ndmin=2)
    return {n: data[:, i] for i, n in enumerate(names)}
