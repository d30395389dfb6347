#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The tree keeps its layers (doc/architecture.md):

* every file under src_fix/lib/ (the plain C++ kernels) includes only the standard library,
  third-party libraries (Eigen, MPI, hypre) and other files of src_fix/lib/: no LIGGGHTS
  header (lammps.h, fix.h, pointers.h, ...) and no quoted path that leaves src_fix/lib/;
* inside src_fix/lib/, a folder includes only the folders below it (KERNEL_ARROWS; a new
  kernel folder declares its arrows there);
* no two folders or files of src_fix/, post/ or tests/ differ only by case (they would merge
  on a case-insensitive checkout, macOS or Windows).

    check_layers.py SOURCE_DIR [--liggghts-include DIR]   exit 1 and a list if anything breaks
    check_layers.py --self-test                           the check finds planted breaches

With --liggghts-include, every header name found in that folder counts as a LIGGGHTS header
too (the build passes Debian's /usr/include/liggghts).
"""
import os
import re
import sys
import tempfile

KERNEL_ROOT = os.path.join("src_fix", "lib")
CASE_CHECKED = ("src_fix", "post", "tests")
SKIPPED_DIRS = {"__pycache__"}
# LAMMPS/LIGGGHTS' own headers, whatever their folder: the kernels know none of them.
LIGGGHTS_HEADERS = {
    "lammps.h", "pointers.h", "lmptype.h", "fix.h", "compute.h", "pair.h", "atom.h", "atom_vec.h",
    "modify.h", "update.h", "error.h", "comm.h", "force.h", "memory.h", "input.h", "group.h",
    "variable.h", "domain.h", "neighbor.h", "neigh_list.h", "output.h", "timer.h", "universe.h",
    "library.h", "style_fix.h", "style_compute.h", "fix_property_atom.h",
    "fix_property_global.h", "math_extra.h", "math_extra_liggghts.h", "properties.h",
}
LIGGGHTS_PREFIXES = ("fix_", "compute_", "pair_", "style_", "contact_models", "granular_")
# The arrows inside src_fix/lib/ (doc/architecture.md): each folder and what it may include.
KERNEL_ARROWS = {
    "common": {"common"},
    "contact": {"contact", "common"},
    "network": {"network", "common"},
    "conduction": {"conduction", "network", "contact", "common"},
    "writers": {"writers", "common"},
    "catalog": {"catalog"},
    "lubrication": {"lubrication", "common"},
}
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)


def source_files(root):
    for folder, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if d not in SKIPPED_DIRS and not d.startswith("."))
        for name in sorted(files):
            if name.endswith((".h", ".hpp", ".cpp", ".inc")):
                yield os.path.join(folder, name)


def is_liggghts(name, extra):
    base = os.path.basename(name)
    return base in LIGGGHTS_HEADERS or base in extra or base.startswith(LIGGGHTS_PREFIXES)


def include_problems(src, extra):
    """Includes of the kernels that leave src_fix/lib or name a LIGGGHTS header."""
    lib = os.path.realpath(os.path.join(src, KERNEL_ROOT))
    out = []
    for path in source_files(lib):
        rel = os.path.relpath(path, src)
        text = open(path, encoding="utf-8", errors="replace").read()
        for kind, name in INCLUDE.findall(text):
            if is_liggghts(name, extra) and kind == "<":
                out.append("%s: includes the LIGGGHTS header <%s>" % (rel, name))
                continue
            if kind == "<":
                continue
            # A quoted include resolves beside the file or from the src_fix/lib root, and
            # must land inside src_fix/lib.
            here = os.path.realpath(os.path.join(os.path.dirname(path), name))
            rooted = os.path.realpath(os.path.join(lib, name))
            found = [p for p in (here, rooted) if os.path.isfile(p)]
            if is_liggghts(name, extra) and not found:
                out.append('%s: includes the LIGGGHTS header "%s"' % (rel, name))
            elif not found:
                out.append('%s: includes "%s", which is not a file of %s/' % (rel, name, KERNEL_ROOT))
            elif not all(p == lib or p.startswith(lib + os.sep) for p in found):
                out.append('%s: includes "%s", outside %s/' % (rel, name, KERNEL_ROOT))
            else:
                source = os.path.relpath(path, lib).split(os.sep)[0]
                target = os.path.relpath(found[0], lib).split(os.sep)[0]
                allowed = KERNEL_ARROWS.get(source)
                if allowed is None:
                    out.append("%s: the kernel folder '%s' has no declared arrows "
                               "(KERNEL_ARROWS in %s)" % (rel, source, os.path.basename(__file__)))
                elif target not in allowed:
                    out.append('%s: includes "%s": %s/ may include only %s' %
                               (rel, name, source, ", ".join(sorted(allowed))))
    return out


def case_problems(src):
    """Paths of src_fix/, post/, tests/ that differ only by case."""
    out = []
    for top in CASE_CHECKED:
        for folder, dirs, files in os.walk(os.path.join(src, top)):
            dirs[:] = sorted(d for d in dirs if d not in SKIPPED_DIRS and not d.startswith("."))
            seen = {}
            for name in sorted(dirs + files):
                twin = seen.setdefault(name.lower(), name)
                if twin != name:
                    rel = os.path.relpath(folder, src)
                    out.append("%s: '%s' and '%s' differ only by case" % (rel, twin, name))
    return out


def problems(src, liggghts_include=None):
    extra = set()
    if liggghts_include and os.path.isdir(liggghts_include):
        extra = {n for n in os.listdir(liggghts_include) if n.endswith(".h")}
    return include_problems(src, extra) + case_problems(src)


def self_test():
    """Plant each breach in a small tree and check that it is found (and that a clean tree
    passes)."""
    with tempfile.TemporaryDirectory() as root:
        def write(rel, text=""):
            path = os.path.join(root, rel)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)

        write("src_fix/lib/contact/a.h", '#include <cmath>\n#include "common/b.h"\n')
        write("src_fix/lib/common/b.h", '#include "c.h"\n')
        write("src_fix/lib/common/c.h")
        write("src_fix/BEARING/fix_x.h", '#include "fix.h"\n')  # a style may
        write("post/core/d.h")
        if problems(root):
            print("self-test: a clean tree was refused: %s" % problems(root))
            return 1
        write("src_fix/lib/contact/e.cpp", '#include "pointers.h"\n#include <lammps.h>\n'
              '#include "support/args.h"\n#include "../BEARING/fix_x.h"\n')
        write("src_fix/support/args.h")
        write("src_fix/lib/Contact/f.h")
        write("src_fix/lib/common/up.h", '#include "contact/a.h"\n')
        write("post/Core/g.h")
        found = "\n".join(problems(root))
        expected = ['e.cpp: includes the LIGGGHTS header "pointers.h"',
                    "e.cpp: includes the LIGGGHTS header <lammps.h>",
                    'e.cpp: includes "support/args.h", which is not a file of',
                    'e.cpp: includes "../BEARING/fix_x.h"',
                    "'Contact' and 'contact' differ only by case",
                    'up.h: includes "contact/a.h": common/ may include only common',
                    "'Core' and 'core' differ only by case"]
        missed = [e for e in expected if e not in found]
        if missed:
            print("self-test: not found: %s\nfound:\n%s" % (missed, found))
            return 1
    print("self-test: every planted breach found")
    return 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) not in (2, 4) or (len(argv) == 4 and argv[2] != "--liggghts-include"):
        print(__doc__)
        return 2
    found = problems(argv[1], argv[3] if len(argv) == 4 else None)
    for p in found:
        print(p)
    print("layers: %d problem(s)" % len(found))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
