#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Every test carries exactly one cost tier among its labels: unit, integration or validation
(tests/README.md).

  check_tiers.py BUILD_DIR           reads the build's test list (ctest --show-only=json-v1)
  check_tiers.py --self-test         a planted list: one test without a tier, one with two
  check_tiers.py --times LOG BUILD   the tests of a run that took longer than their tier
                                     allows (LOG: a copy of ctest's Testing/Temporary/
                                     LastTest.log); a report, for scripts/test.sh
"""
import json
import os
import re
import subprocess
import sys
import tempfile

TIERS = ("unit", "integration", "validation")
# What each tier allows (s), as tests/README.md states it: the report names the tests over it.
BUDGET = {"unit": 1.0, "integration": 30.0}


def problems(tests):
    """The tests whose labels hold no tier or more than one, as 'name: reason' lines."""
    out = []
    for t in tests:
        labels = []
        for p in t.get("properties", []):
            if p.get("name") == "LABELS":
                labels = p.get("value", [])
        tiers = [x for x in labels if x in TIERS]
        if len(tiers) != 1:
            why = "no tier" if not tiers else "tiers " + ", ".join(tiers)
            out.append(f"{t['name']}: {why} (labels: {';'.join(labels) or 'none'})")
    return out


def test_list(build):
    # ctest writes its log into the folder it lists: a folder of our own that includes the
    # build's tests, so that the build's own log (which a running ctest is writing) is kept
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "CTestTestfile.cmake"), "w") as f:
            f.write(f'subdirs("{os.path.abspath(build)}")\n')
        res = subprocess.run(["ctest", "--test-dir", tmp, "--show-only=json-v1"],
                             capture_output=True, text=True, check=True)
    return json.loads(res.stdout)["tests"]


def self_test():
    planted = [
        {"name": "a.ok", "properties": [{"name": "LABELS", "value": ["post", "unit"]}]},
        {"name": "b.none", "properties": [{"name": "LABELS", "value": ["post"]}]},
        {"name": "c.two", "properties": [{"name": "LABELS", "value": ["unit", "validation"]}]},
        {"name": "d.unlabelled", "properties": []},
    ]
    found = problems(planted)
    want = ["b.none: no tier (labels: post)", "c.two: tiers unit, validation (labels: "
            "unit;validation)", "d.unlabelled: no tier (labels: none)"]
    if found != want:
        print("check_tiers self-test FAILED:\n  " + "\n  ".join(found))
        return 1
    print("check_tiers: every planted problem found")
    return 0


def over_budget(log, tiers_of):
    """(name, seconds, tier) of the tests in ctest's LastTest.log over their tier's budget."""
    text = open(log, errors="replace").read()
    out = []
    for m in re.finditer(r'^\d+/\d+ Test: (\S+)\n.*?^Test time = +([0-9.]+) sec', text,
                         re.S | re.M):
        name, secs = m.group(1), float(m.group(2))
        tier = tiers_of.get(name)
        if tier in BUDGET and secs > BUDGET[tier]:
            out.append((name, secs, tier))
    return out


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) == 4 and argv[1] == "--times":
        tests = test_list(argv[3])
        tiers_of = {}
        for t in tests:
            for p in t.get("properties", []):
                if p.get("name") == "LABELS":
                    for x in p.get("value", []):
                        if x in TIERS:
                            tiers_of[t["name"]] = x
        late = over_budget(argv[2], tiers_of)
        for name, secs, tier in late:
            print(f"tiers: {name} took {secs:.1f} s, over the {tier} tier's {BUDGET[tier]:g} s")
        if not late:
            print("tiers: every test within its tier's time")
        return 0
    if len(argv) != 2:
        print(__doc__)
        return 2
    tests = test_list(argv[1])
    found = problems(tests)
    for line in found:
        print(line)
    counts = {tier: 0 for tier in TIERS}
    for t in tests:
        for p in t.get("properties", []):
            if p.get("name") == "LABELS":
                for x in p.get("value", []):
                    if x in counts:
                        counts[x] += 1
    print("tiers: " + ", ".join(f"{counts[k]} {k}" for k in TIERS) +
          f"; {len(found)} problem(s) in {len(tests)} tests")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
