#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The README's commands are a test: every command of README.md's code blocks runs as written,
block after block in one shell from the root of a fresh copy of the repository (its tracked
files, with build/ a link to the build given and ../shared beside it when the source tree has
it), and prints or writes what the README says (tests/packaging/readme_claims.txt). Fails on a
command that fails, a claim that does not hold, a claim or command the other does not know, a
file left in the copy's root (outside results/) and a tracked file changed.

    readme_commands.py SOURCE_DIR BUILD_DIR [--tier integration|validation] [--keep DIR]
    readme_commands.py --self-test

--tier integration runs the blocks whose every command is fast; validation runs them all.
"""
import argparse
import hashlib
import os
import re
import shutil
import subprocess
import sys
import tempfile


def blocks(readme):
    """The README's code blocks (fences without a language or with sh), each a list of
    commands: lines joined at a trailing backslash, blank lines dropped."""
    out, cur, inside = [], None, False
    for line in open(readme, encoding="utf-8").read().splitlines():
        if line.startswith("```"):
            if inside:
                out.append(cur)
                inside = False
            elif line.strip() in ("```", "```sh"):
                cur, inside = [], True
            continue
        if inside:
            if cur and cur[-1].endswith("\\"):
                cur[-1] = cur[-1][:-1].rstrip() + " " + line.strip()
            elif line.strip():
                cur.append(line.strip())
    return [b for b in out if b]


def claims(path):
    """PIECE | KIND: VALUE lines ('#' comments): the claims on the command holding PIECE."""
    out = []
    for n, line in enumerate(open(path, encoding="utf-8"), 1):
        if not line.strip() or line.startswith("#"):
            continue
        piece, sep, claim = line.rstrip("\n").partition(" | ")
        kind, sep2, value = claim.partition(": ")
        if not sep or not sep2 or kind not in ("out", "not", "file", "tier", "needs", "skip"):
            raise SystemExit(f"ERROR: {path}:{n}: expected 'PIECE | out|not|file|tier|needs|skip: "
                             f"VALUE', got {line.strip()!r}")
        out.append((n, piece.strip(), kind, value.strip()))
    return out


def bind(commands, table, path):
    """Each claim to the one command holding its piece; errors for none or several."""
    by = {c: [] for c in commands}
    errors = []
    for n, piece, kind, value in table:
        hits = [c for c in commands if piece in c]
        if len(hits) != 1:
            errors.append(f"{path}:{n}: '{piece}' is in {len(hits)} README commands, not one")
        else:
            by[hits[0]].append((kind, value))
    return by, errors


def snapshot(root):
    """Every file under root (links not followed) and its digest."""
    files = {}
    for d, dirs, names in os.walk(root):
        for name in names:
            p = os.path.join(d, name)
            if os.path.isfile(p) and not os.path.islink(p):
                files[os.path.relpath(p, root)] = hashlib.sha256(open(p, "rb").read()).hexdigest()
    return files


def copy_tree(source, dest):
    """The tracked files of the source's working tree (as they are now), into dest."""
    names = subprocess.run(["git", "-C", source, "ls-files", "-z"], capture_output=True,
                           check=True).stdout.decode().split("\0")
    for name in filter(None, names):
        src = os.path.join(source, name)
        if not os.path.lexists(src):  # deleted in the working tree
            continue
        os.makedirs(os.path.dirname(os.path.join(dest, name)) or dest, exist_ok=True)
        shutil.copy2(src, os.path.join(dest, name), follow_symlinks=False)


def run(a):
    readme = os.path.join(a.source, "README.md")
    table = claims(os.path.join(a.source, "tests", "packaging", "readme_claims.txt"))
    bl = blocks(readme)
    commands = [c for b in bl for c in b]
    by, errors = bind(commands, table, "readme_claims.txt")
    for e in errors:
        print("FAIL " + e)
    work = a.keep or tempfile.mkdtemp(prefix="readme_")
    repo = os.path.join(work, "repo")
    if os.path.exists(repo):
        shutil.rmtree(repo)
    os.makedirs(repo)
    copy_tree(a.source, repo)
    os.symlink(os.path.abspath(a.build), os.path.join(repo, "build"))
    shared = os.path.join(os.path.dirname(os.path.abspath(a.source)), "shared")
    if os.path.isdir(shared) and not os.path.lexists(os.path.join(work, "shared")):
        os.symlink(shared, os.path.join(work, "shared"))
    before = snapshot(repo)
    failed = bool(errors)
    ran = skipped = 0
    for b in bl:
        tiers = {v for c in b for k, v in by[c] if k == "tier"}
        if a.tier == "integration" and "validation" in tiers:
            print(f"skip (validation tier) block: {b[0][:70]}")
            skipped += len(b)
            continue
        # one shell per block, from the root: a cd holds until the block's end
        script = ""
        for i, c in enumerate(b):
            reasons = [v for k, v in by[c] if k == "skip"]
            missing = [v for k, v in by[c] if k == "needs"
                       if not os.path.exists(os.path.join(repo, v))]
            if reasons or missing:
                why = reasons[0] if reasons else f"{missing[0]} not found"
                print(f"skip ({why}): {c[:90]}")
                skipped += 1
                continue
            # its standard error with its output; the braces keep a cd in this shell
            script += (f"echo '@@@ {i} start'\n{{ {c}\n}} 2>&1\nstatus=$?\n"
                       f"echo \"@@@ {i} exit $status\"\n[ $status = 0 ] || exit 1\n")
        if not script:
            continue
        r = subprocess.run(["bash", "-c", script], cwd=repo, capture_output=True, text=True,
                           # the model cache of this copy: the user's own cache neither feeds
                           # nor gets the README's banks
                           env=dict(os.environ, LC_ALL="C.UTF-8",
                                    OHMDEM_CACHE=os.path.join(work, "cache")))
        text = r.stdout + "\n" + r.stderr
        outputs = dict(re.findall(r"^@@@ (\d+) start\n(.*?)^@@@ \1 exit", r.stdout, re.S | re.M))
        statuses = dict(re.findall(r"^@@@ (\d+) exit (\d+)$", r.stdout, re.M))
        for i, c in enumerate(b):
            if str(i) not in statuses:
                continue
            ran += 1
            out = outputs.get(str(i), "")
            if statuses[str(i)] != "0":
                print(f"FAIL exit {statuses[str(i)]}: {c}\n{out[-2000:]}{r.stderr[-2000:]}")
                failed = True
                continue
            for kind, value in by[c]:
                if kind == "out" and not re.search(value, out, re.M):
                    print(f"FAIL '{value}' not printed by: {c}\n{out[-1500:]}")
                    failed = True
                elif kind == "not" and re.search(value, out, re.M):
                    print(f"FAIL '{value}' printed by: {c}")
                    failed = True
                elif kind == "file":
                    p = os.path.join(repo, value)
                    if not (os.path.isfile(p) and os.path.getsize(p) > 0):
                        print(f"FAIL {value} not written by: {c}")
                        failed = True
            print(f"ok   {c[:100]}")
        if r.returncode != 0 and all(s == "0" for s in statuses.values()):
            print(f"FAIL the block stopped (exit {r.returncode}) at: {b[0][:70]}\n{text[-1500:]}")
            failed = True
    after = snapshot(repo)
    left = sorted({p.split(os.sep)[0] for p in set(after) - set(before)} - {"results"})
    left += sorted(n for n in os.listdir(repo) if n not in {"build", "results"}
                   and not os.path.exists(os.path.join(a.source, n)) and n not in left)
    if left:
        print("FAIL left in the repository's root: " + ", ".join(left))
        failed = True
    changed = sorted(p for p in before if after.get(p) != before[p])
    if changed:
        print("FAIL tracked files changed: " + ", ".join(changed))
        failed = True
    if not a.keep:
        shutil.rmtree(work, ignore_errors=True)
    print(f"readme commands: {ran} run, {skipped} skipped, "
          f"{'FAILED' if failed else 'passed'}")
    return 1 if failed else 0


def self_test():
    """A planted README: a failing command, a claim not printed, a file left in the root, a
    tracked file overwritten, a claim naming no command: each is found."""
    with tempfile.TemporaryDirectory(prefix="readme_self_") as d:
        src = os.path.join(d, "src")
        os.makedirs(os.path.join(src, "tests", "packaging"))
        os.makedirs(os.path.join(d, "build"))
        with open(os.path.join(src, "README.md"), "w") as f:
            f.write("# x\n\n```\nmkdir -p results\necho hello > results/a.txt\necho 5 \\\n"
                    "  apples\nfalse\n```\n\n```sh\necho stray > left.txt\n"
                    "echo new > README.md\n```\n")
        with open(os.path.join(src, "tests", "packaging", "readme_claims.txt"), "w") as f:
            f.write("# claims\necho hello | file: results/a.txt\necho 5 apples | out: ^5 pears$\n"
                    "echo nothing | out: x\n")
        subprocess.run(["git", "init", "-q", src], check=True)
        subprocess.run(["git", "-C", src, "add", "."], check=True)
        r = subprocess.run([sys.executable, __file__, src, os.path.join(d, "build")],
                           capture_output=True, text=True)
        expect = ["'echo nothing' is in 0 README commands", "'^5 pears$' not printed",
                  "FAIL exit 1: false", "left in the repository's root: left.txt",
                  "tracked files changed: README.md", "FAILED"]
        missing = [e for e in expect if e not in r.stdout]
        if missing or r.returncode == 0:
            print(r.stdout)
            print("readme self-test: not found: " + "; ".join(missing))
            return 1
    print("readme self-test: every planted problem found")
    return 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    ap = argparse.ArgumentParser()
    ap.add_argument("source")
    ap.add_argument("build")
    ap.add_argument("--tier", choices=["integration", "validation"], default="validation")
    ap.add_argument("--keep", metavar="DIR", help="work in DIR and keep it")
    return run(ap.parse_args())


if __name__ == "__main__":
    sys.exit(main())
