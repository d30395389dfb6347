#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""doc/architecture.md names every module of the tree it maps: each source file of src_fix/lib/
<folder>/, src_fix/support/, post/<layer>/, each script of studies/ and each folder of bench/
appears, by its file name without extension, in the map's tree block (the first ``` block).
post/cli's cmd_<name>.cpp are named by the map's rule for them.

  check_map.py SOURCE_DIR       the names missing from the map, one per line (exit 1 if any)
  check_map.py --self-test      a planted tree and map: the check finds the one missing name
"""
import os
import re
import sys

# (folder under the source root, what a module is there)
AREAS = [("src_fix/lib", "files"), ("src_fix/support", "files"), ("post", "files"),
         ("studies", "files"), ("bench", "folders")]
SOURCE_EXT = (".h", ".cpp", ".py", ".sh")


def modules(root):
    """(area-relative folder, name) of every module the map must name."""
    out = set()
    for area, kind in AREAS:
        base = os.path.join(root, area)
        if not os.path.isdir(base):
            continue
        if kind == "folders":
            for d in sorted(os.listdir(base)):
                if os.path.isdir(os.path.join(base, d)):
                    out.add((area, d))
            continue
        for folder, dirs, files in os.walk(base):
            dirs[:] = [d for d in dirs if d not in ("__pycache__",)]
            for f in files:
                stem, ext = os.path.splitext(f)
                if ext not in SOURCE_EXT or f == "CMakeLists.txt":
                    continue
                rel = os.path.relpath(folder, root)
                if rel == "post/cli" and stem.startswith("cmd_"):
                    continue  # the map's rule: one cmd_<name>.cpp per command
                if stem in ("main", "__init__"):
                    continue
                out.add((rel, stem))
    return out


def tree_words(map_text):
    m = re.search(r"```\n(.*?)```", map_text, re.S)
    if not m:
        return set()
    return set(re.findall(r"[A-Za-z0-9_]+", m.group(1)))


def missing(root, map_text):
    words = tree_words(map_text)
    return sorted(f"{folder}/{name}" for folder, name in modules(root) if name not in words)


def self_test():
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        for f in ("post/dsp/fft.cpp", "post/dsp/fft.h", "post/dsp/hidden_filter.cpp",
                  "post/cli/cmd_spectrum.cpp", "studies/common.py", "bench/signal/x.sh"):
            os.makedirs(os.path.join(tmp, os.path.dirname(f)), exist_ok=True)
            open(os.path.join(tmp, f), "w").close()
        planted = "# Map\n```\npost/\n  dsp/  fft\nstudies/ common\nbench/ signal\n```\n"
        found = missing(tmp, planted)
    if found != ["post/dsp/hidden_filter"]:
        print("check_map self-test FAILED: " + ", ".join(found))
        return 1
    print("check_map: the planted missing module found, nothing else")
    return 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) != 2:
        print(__doc__)
        return 2
    root = argv[1]
    found = missing(root, open(os.path.join(root, "doc", "architecture.md")).read())
    for name in found:
        print(f"doc/architecture.md: the map does not name {name}")
    if found:
        print(f"{len(found)} module(s) missing from the map")
        return 1
    print("doc/architecture.md names every module of src_fix/lib, src_fix/support, post, "
          "studies and bench")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
