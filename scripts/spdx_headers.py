#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""SPDX license lines in every source file of ohmdem (C++, CMake, shell, Python).

    scripts/spdx_headers.py --check   lists the files without the line, exit 1 if any
    scripts/spdx_headers.py --add     adds the line where it is missing (after a #! line)

The files are those git knows (tracked, or new and not ignored), else a walk of the tree.
Re-run --add after merging branches that bring new files; tests/packaging runs --check.
"""
import os
import subprocess
import sys

LICENSE = "GPL-2.0-or-later"
TAG = "SPDX-License-Identifier: " + LICENSE
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Not ours, or not a source file: the session machinery (.ci) and generated reference tables.
EXCLUDED_PREFIXES = (".ci/",)
EXCLUDED_FILES = {"tests/lib/contact/hertz_reference.inc"}
SKIPPED_DIRS = {".git", "__pycache__", "demo-output", "bench_stock_out"}


def comment_for(path):
    """The line comment of a source file's language, or None for other files."""
    name = os.path.basename(path)
    if name.endswith((".cpp", ".h")):
        return "//"
    if name == "CMakeLists.txt" or name.endswith((".cmake", ".sh", ".py")):
        return "#"
    return None


def candidate_files():
    try:
        out = subprocess.run(
            ["git", "-C", ROOT, "ls-files", "--cached", "--others", "--exclude-standard"],
            check=True, capture_output=True, text=True).stdout
        files = [f for f in out.splitlines() if os.path.isfile(os.path.join(ROOT, f))]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for top, dirs, names in os.walk(ROOT):
            dirs[:] = [d for d in dirs
                       if d not in SKIPPED_DIRS and not d.startswith(("build", "out"))]
            files += [os.path.relpath(os.path.join(top, n), ROOT) for n in names]
    return sorted(f for f in files
                  if comment_for(f) and f not in EXCLUDED_FILES
                  and not f.startswith(EXCLUDED_PREFIXES))


def has_tag(path):
    with open(os.path.join(ROOT, path), encoding="utf-8", errors="replace") as f:
        head = [next(f, "") for _ in range(5)]
    return any(TAG in line for line in head)


def add_tag(path):
    full = os.path.join(ROOT, path)
    with open(full, encoding="utf-8") as f:
        text = f.read()
    line = comment_for(path) + " " + TAG + "\n"
    if text.startswith("#!"):
        end = text.find("\n") + 1
        text = text[:end] + line + text[end:]
    else:
        text = line + text
    with open(full, "w", encoding="utf-8") as f:
        f.write(text)


def main(argv):
    if len(argv) != 2 or argv[1] not in ("--check", "--add"):
        sys.stderr.write("usage: spdx_headers.py --check | --add\n")
        return 2
    missing = [f for f in candidate_files() if not has_tag(f)]
    if argv[1] == "--add":
        for f in missing:
            add_tag(f)
        print("spdx: added the line to %d file(s)" % len(missing))
        return 0
    for f in missing:
        print("ERROR: %s: no '%s' line in its first 5 lines" % (f, TAG))
    print("spdx: %d source file(s) checked, %d without the line"
          % (len(candidate_files()), len(missing)))
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
