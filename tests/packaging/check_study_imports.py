#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The studies import each other without a circle (doc/architecture.md: studies/ on common.py;
a study that needs another's helpers imports it, never the other way round as well): every
import among studies/*.py, at the top or deferred inside a function, is an arrow of one graph,
which must have no cycle.

  check_study_imports.py SOURCE_DIR    the cycles, one per line (exit 1 if any)
  check_study_imports.py --self-test   a planted circle through a deferred import is found
"""
import ast
import os
import sys
import tempfile


def graph(folder):
    mods = {f[:-3] for f in os.listdir(folder) if f.endswith(".py")}
    g = {}
    for m in mods:
        tree = ast.parse(open(os.path.join(folder, m + ".py")).read(), m + ".py")
        names = set()
        for node in ast.walk(tree):  # every import, deferred ones too
            if isinstance(node, ast.Import):
                names |= {a.name for a in node.names}
            elif isinstance(node, ast.ImportFrom) and node.module:
                names.add(node.module)
        g[m] = sorted(names & mods)
    return g


def cycles(g):
    found, done = [], set()

    def visit(m, path):
        if m in path:
            cyc = path[path.index(m):] + [m]
            if sorted(cyc[:-1]) not in [sorted(c[:-1]) for c in found]:
                found.append(cyc)
            return
        if m in done:
            return
        for n in g[m]:
            visit(n, path + [m])
        done.add(m)

    for m in sorted(g):
        visit(m, [])
    return found


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        files = {"common.py": "", "a.py": "import common\nimport b\n",
                 "b.py": "import common\n\ndef f():\n    import a\n", "c.py": "import a\n"}
        for name, text in files.items():
            open(os.path.join(tmp, name), "w").write(text)
        found = cycles(graph(tmp))
    if [sorted(c[:-1]) for c in found] != [["a", "b"]]:
        print("check_study_imports self-test FAILED: " + repr(found))
        return 1
    print("check_study_imports: the planted circle found, nothing else")
    return 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) != 2:
        print(__doc__)
        return 2
    g = graph(os.path.join(argv[1], "studies"))
    found = cycles(g)
    for c in found:
        print("studies: an import circle: " + " -> ".join(c))
    print(f"study imports: {len(g)} studies, {len(found)} circle(s)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
