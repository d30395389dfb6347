#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Says why tests were skipped, at the end of ctest's normal output (CTestCustom.cmake runs it
after the tests: ctest alone prints "***Skipped" and no reason).

Reads ctest's Testing/Temporary/LastTest.log(.tmp): a test that printed a GoogleTest skip ("...:
Skipped" followed by the reason) or a line starting with SKIP (the Python drivers, exit 77)
is listed with that reason. Then the tests not registered at all for want of their data (the
lines of NOT_REGISTERED, written at configure time).

Usage: skip_reasons.py LASTTEST_LOG [NOT_REGISTERED]
"""
import re
import sys


def reasons(log_text):
    """(test name, reason) for each skipped test of a LastTest.log."""
    out = []
    # Each test: '"NAME" start time:' ... 'Output:' dashes OUTPUT '<end of output>'
    for m in re.finditer(r'^"(?P<name>[^"]+)" start time:.*?\nOutput:\n-+\n(?P<out>.*?)'
                         r'<end of output>', log_text, re.S | re.M):
        text = m.group("out")
        why = None
        g = re.search(r":\d+: Skipped\n(?P<why>.*?)\n\s*\n?\[  SKIPPED \]", text, re.S)
        if g:
            why = " ".join(g.group("why").split()) or "(no reason given)"
        elif "[  SKIPPED ]" in text:
            why = "(no reason given)"
        else:
            s = re.search(r"^SKIP(?:PED)?:?\s*(?P<why>.*)$", text, re.M)
            if s:
                why = s.group("why").strip()
        if why:
            out.append((m.group("name"), why))
    return out


# A LastTest.log in ctest 3.25's layout: a GoogleTest skip, a Python driver's skip, a pass.
SAMPLE = """----------------------------------------------------------
"post.Detect.Cwru" start time: Nov 25 00:36 UTC
Output:
----------------------------------------------------------
[ RUN      ] Detect.Cwru
/src/tests/post/dsp/test_detect.cpp:425: Skipped
/work/shared/data/bearing-real not found

[  SKIPPED ] Detect.Cwru (0 ms)
<end of output>
----------------------------------------------------------
"reliability_full_disk" start time: Nov 25 00:36 UTC
Output:
----------------------------------------------------------
SKIPPED: full_disk needs a small file system and mount is not allowed here
<end of output>
----------------------------------------------------------
"signal.Write" start time: Nov 25 00:36 UTC
Output:
----------------------------------------------------------
[ RUN      ] Signal.Write
[       OK ] Signal.Write (0 ms)
<end of output>
"""


def self_test():
    got = reasons(SAMPLE)
    want = [("post.Detect.Cwru", "/work/shared/data/bearing-real not found"),
            ("reliability_full_disk",
             "full_disk needs a small file system and mount is not allowed here")]
    print("skip reasons: ok" if got == want else f"skip reasons: got {got}, want {want}")
    return 0 if got == want else 1


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    # While the tests run ctest writes LastTest.log.tmp, renamed to LastTest.log after this
    # script: the .tmp file is this run's.
    found = []
    for log in (sys.argv[1] + ".tmp", sys.argv[1]):
        try:
            with open(log, errors="replace") as f:
                found = reasons(f.read())
            break
        except OSError:
            continue
    missing = []
    if len(sys.argv) > 2:
        try:
            with open(sys.argv[2]) as f:
                missing = [l.rstrip("\n") for l in f if l.strip()]
        except OSError:
            pass
    if found:
        print("Skipped tests and why:")
        for name, why in found:
            print(f"  {name}: {why}")
    if missing:
        print("Tests not registered (their data is missing; re-run cmake once it is there):")
        for line in missing:
            print(f"  {line}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
