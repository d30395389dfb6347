#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Stock equivalence: run one LIGGGHTS deck with stock `liggghts` and with `ohmdem`, compare
the thermo output of the two log files.

usage: compare_thermo.py --stock EXE --ohmdem EXE --deck FILE --workdir DIR
                         [--copy PATH ...] [--var NAME VALUE ...] [--timeout S]
                         [--passes K] [--var-ohmdem NAME VALUE ...]

Each executable runs in its own fresh sub-directory of --workdir (emptied first), holding a
copy of the deck, of every --copy path (file or directory, e.g. the deck's meshes/) and an
empty post/. What is compared: every thermo block of log.liggghts, i.e. the lines from a
header line starting with "Step" up to (not including) its "Loop time" line; INFO/WARNING
lines printed inside a block (particle insertion reports) are compared too. Timing, memory
and date lines are outside the blocks. Exit 0 if identical, 1 otherwise, 77 (ctest SKIP) when
the stock executable is missing.

--passes K: the deck loops K times through clear/next/jump over the same setup; the thermo
blocks must also form K identical groups (the setup after `clear` behaves as the first one).
--var-ohmdem: extra -var given to ohmdem only (self-check that a difference is detected).
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

SKIP = 77
IGNORE = ('Loop time', 'Memory usage', 'Performance', 'Setting up run', 'time (%)')


def thermo_blocks(log_path):
    """List of thermo blocks, each a list of lines (trailing blanks stripped)."""
    blocks, cur = [], None
    with open(log_path, errors='replace') as f:
        for line in f:
            line = line.rstrip()
            words = line.split()
            if words and words[0] == 'Step':
                cur = [line]
                blocks.append(cur)
            elif cur is not None:
                if line.startswith('Loop time'):
                    cur = None
                elif line and not any(k in line for k in IGNORE):
                    cur.append(line)
    return blocks


def run(exe, args, wd, extra, timeout):
    if os.path.exists(wd):
        shutil.rmtree(wd)
    os.makedirs(os.path.join(wd, 'post'))
    shutil.copy(args.deck, wd)
    for p in args.copy:
        dst = os.path.join(wd, os.path.basename(p.rstrip('/')))
        (shutil.copytree if os.path.isdir(p) else shutil.copy)(p, dst)
    cmd = [exe, '-in', os.path.basename(args.deck), '-log', 'log.liggghts', '-echo', 'log'] + extra
    t0 = time.time()
    with open(os.path.join(wd, 'screen.txt'), 'w') as out:
        try:
            rc = subprocess.run(cmd, cwd=wd, stdout=out, stderr=subprocess.STDOUT,
                                stdin=subprocess.DEVNULL, timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            rc = 'timeout after %g s' % timeout
    dt = time.time() - t0
    print('%-8s %s  (in %s): exit %s, %.2f s' % (os.path.basename(wd), ' '.join(cmd), wd, rc, dt))
    log = os.path.join(wd, 'log.liggghts')
    with open(os.path.join(wd, 'screen.txt'), errors='replace') as f:
        screen = f.read()
    if rc != 0 or 'ERROR' in screen or not os.path.exists(log):
        print(screen[-3000:])
        sys.exit('FAIL: %s did not run the deck cleanly (exit %s)' % (exe, rc))
    return thermo_blocks(log)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--stock', required=True)
    ap.add_argument('--ohmdem', required=True)
    ap.add_argument('--deck', required=True)
    ap.add_argument('--workdir', required=True)
    ap.add_argument('--copy', nargs='*', default=[])
    ap.add_argument('--var', nargs=2, action='append', default=[], metavar=('NAME', 'VALUE'))
    ap.add_argument('--timeout', type=float, default=300)
    ap.add_argument('--passes', type=int, default=1)
    ap.add_argument('--var-ohmdem', nargs=2, action='append', default=[], metavar=('NAME', 'VALUE'))
    args = ap.parse_args()
    if not (os.path.isfile(args.stock) and os.access(args.stock, os.X_OK)):
        print('SKIP: stock LIGGGHTS executable %r not found (Debian package liggghts)' % args.stock)
        return SKIP
    extra = [w for nv in args.var for w in ('-var',) + tuple(nv)]
    ref = run(args.stock, args, os.path.join(args.workdir, 'stock'), extra, args.timeout)
    extra_o = extra + [w for nv in args.var_ohmdem for w in ('-var',) + tuple(nv)]
    got = run(args.ohmdem, args, os.path.join(args.workdir, 'ohmdem'), extra_o, args.timeout)

    nrows = sum(len(b) - 1 for b in ref)
    if not ref or nrows < 2:
        print('FAIL: no thermo output in the stock log')
        return 1
    if len(ref) != len(got):
        print('FAIL: %d thermo blocks with stock liggghts, %d with ohmdem' % (len(ref), len(got)))
        return 1
    for i, (a, b) in enumerate(zip(ref, got)):
        for j in range(max(len(a), len(b))):
            la = a[j] if j < len(a) else '<missing>'
            lb = b[j] if j < len(b) else '<missing>'
            if la != lb:
                print('FAIL: thermo block %d, line %d differs:\n  liggghts: %s\n  ohmdem:   %s'
                      % (i + 1, j + 1, la, lb))
                return 1
    if args.passes > 1:
        n = len(ref) // args.passes
        if n * args.passes != len(ref) or any(ref[k * n:(k + 1) * n] != ref[:n]
                                               for k in range(1, args.passes)):
            print('FAIL: the %d passes of the deck do not print identical thermo blocks'
                  % args.passes)
            return 1
        print('%d passes through clear/next/jump: identical thermo blocks in each' % args.passes)
    print('PASS: %d thermo blocks, %d lines, identical (last: %s)'
          % (len(ref), nrows, ref[-1][-1].strip()))
    return 0


if __name__ == '__main__':
    sys.exit(main())
