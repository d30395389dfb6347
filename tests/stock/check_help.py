#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""`ohmdem -help` lists every style that stock `liggghts -help` lists, plus a section
"* ohmdem styles" naming at least one of ours.

usage: check_help.py --stock EXE --ohmdem EXE
Without the stock executable, a fixed list of stock granular styles is checked instead.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

# Styles every LIGGGHTS 3.8 build has; used when /usr/bin/liggghts is not there.
FALLBACK = {'Atom styles': ['granular', 'sphere'],
            'Pair styles': ['gran'],
            'Fix styles': ['wall/gran', 'mesh/surface', 'move/mesh', 'nve/sphere',
                           'insert/pack', 'property/global'],
            'Compute styles': ['erotate/sphere', 'pair/gran/local']}


def sections(text):
    """{section title: set of names} for the '* Xxx styles:' blocks of a -help output."""
    out, cur = {}, None
    for line in text.splitlines():
        m = re.match(r'^\* (.+?):?\s*$', line)
        if m:
            cur = out.setdefault(m.group(1).rstrip(':'), set())
        elif cur is not None:
            cur.update(line.split())
    return out


def helptext(exe):
    """Output and exit code of `exe -help` (LIGGGHTS 3.8 leaves -help through Error::done(),
    which exits with status 1: that is stock behaviour, not a failure)."""
    with tempfile.TemporaryDirectory() as tmp:  # -help still writes log.liggghts in the cwd
        r = subprocess.run([exe, '-help'], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           stdin=subprocess.DEVNULL, timeout=60, cwd=tmp)
    text = r.stdout.decode(errors='replace')
    if r.returncode not in (0, 1) or 'Style options' not in text:
        sys.exit('FAIL: %s -help exited with %d\n%s' % (exe, r.returncode, text[-2000:]))
    return text, r.returncode


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--stock', required=True)
    ap.add_argument('--ohmdem', required=True)
    args = ap.parse_args()
    text, rc = helptext(args.ohmdem)
    got = sections(text)
    bad = 0
    if os.path.isfile(args.stock) and os.access(args.stock, os.X_OK):
        stock_text, stock_rc = helptext(args.stock)
        want = sections(stock_text)
        source = args.stock + ' -help'
        if rc != stock_rc:
            print('FAIL: ohmdem -help exits with %d, stock liggghts with %d' % (rc, stock_rc))
            bad += 1
    else:
        want = {k: set(v) for k, v in FALLBACK.items()}
        source = 'built-in list (stock liggghts not found)'
    if not want:
        print('FAIL: no style sections found in ' + source)
        return 1
    for title, names in sorted(want.items()):
        missing = sorted(names - got.get(title, set()))
        if missing:
            bad += 1
            print('FAIL: section "* %s" of ohmdem -help lacks %s' % (title, ' '.join(missing)))
    ours = [k for k in got if k.startswith('ohmdem styles')]
    if not ours:
        print('FAIL: ohmdem -help has no section "* ohmdem styles"')
        bad += 1
    elif not got[ours[0]]:
        print('FAIL: the section "* %s" of ohmdem -help is empty' % ours[0])
        bad += 1
    if bad:
        return 1
    n = sum(len(v) for v in want.values())
    print('PASS: ohmdem -help lists all %d stock styles of %d sections (from %s) and "* %s": %s'
          % (n, len(want), source, ours[0], ' '.join(sorted(got[ours[0]]))))
    return 0


if __name__ == '__main__':
    sys.exit(main())
