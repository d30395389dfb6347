#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Every style page of doc/ (fix_*.md, compute_*.md, command_*.md) has the sections of a
LAMMPS/LIGGGHTS doc page, in order, the plain-text (doc/src/*.txt) syntax block, and says how a
fix or compute behaves under fix_modify (or compute_modify), across runs (start/stop) and during
minimize, and what a command leaves in restart files; the keywords of the Markdown syntax list
and of the plain-text block are the same (a keyword added to one only is named). The command
pages of ohmdem-post (doc/post/*.md but input.md and library.md) and the deck's page
(doc/deck_bearing.md) have the sections of a command page, in order, and at most 150 lines
(doc/post/diagnose.md any length).
Every such page has a Validity section: a table whose last column names the check that gives
each row (a command in backticks anyone can rerun: ctest, a script, a study).

    check_docs.py SOURCE_DIR
"""
import glob
import os
import re
import sys

SECTIONS = ["Syntax", "Examples", "Description", "Output info", "Restart info", "Validity",
            "Restrictions", "Related commands", "Default", "References"]
# a command page of ohmdem-post or the deck: Restart info where it applies
COMMAND_SECTIONS = ["Syntax", "Examples", "Description", "Output info", "Restart info",
                    "Validity", "Restrictions", "Related commands", "Default"]
COMMAND_OPTIONAL = {"Restart info"}
MAX_COMMAND_LINES = 150


def validity_problems(text):
    """The Validity section holds a table whose last column is `check`, each row's check a
    command in backticks."""
    body = text.split("\n## Validity")[-1].split("\n## ")[0] if "\n## Validity" in text else ""
    rows = [r for r in body.splitlines() if r.startswith("|")]
    if len(rows) < 3 or not re.match(r"^\|.*\|\s*check\s*\|\s*$", rows[0]):
        return ["Validity has no table whose last column is 'check'"]
    out = []
    for r in rows[2:]:
        cells = re.split(r"(?<!\\)\|", r.strip())[1:-1]
        if not cells or not re.search(r"`[^`]+`", cells[-1]):
            out.append("Validity row names no check in backticks: " + r[:60])
    return out


def command_page_problems(path):
    text = open(path, encoding="utf-8").read()
    found = re.findall(r"^## (.+?)\s*$", text, flags=re.M)
    out = []
    missing = [s for s in COMMAND_SECTIONS if s not in found and s not in COMMAND_OPTIONAL]
    if missing:
        out.append("missing section(s): " + ", ".join(missing))
    elif [s for s in found if s in COMMAND_SECTIONS] != [s for s in COMMAND_SECTIONS if s in found]:
        out.append("sections out of order: " + ", ".join(found))
    if "## Validity" in text:
        out += validity_problems(text)
    n = text.count("\n")
    # diagnose holds the detection, identification, sizing and placing: no length limit
    if n > MAX_COMMAND_LINES and os.path.basename(path) != "diagnose.md":
        out.append("%d lines, more than %d" % (n, MAX_COMMAND_LINES))
    return out


def keyword_drift(markdown, block):
    """The keywords of the Markdown list and of the plain-text block must be the same."""
    out = []
    listed = set(re.findall(r"^ {2,}\* `([A-Za-z_]+)", markdown, flags=re.M))
    words = set(re.findall(r"[A-Za-z_]+", block))
    for k in sorted(listed - words):
        out.append("'%s' is in the Markdown syntax list but not in the plain-text block" % k)
    line = re.search(r"^keyword = (.*):l$", block, flags=re.M)
    for k in re.findall(r"\{([A-Za-z_/]+)\}", line.group(1) if line else ""):
        if "`" + k not in markdown:
            out.append("keyword '%s' of the plain-text block is not in the Markdown syntax" % k)
    return out


def problems(path):
    text = open(path, encoding="utf-8").read()
    name = os.path.basename(path)
    kind = name.split("_")[0]  # fix, compute or command
    found = re.findall(r"^## (.+?)\s*$", text, flags=re.M)
    out = []
    missing = [s for s in SECTIONS if s not in found]
    if missing:
        out.append("missing section(s): " + ", ".join(missing))
    elif [s for s in found if s in SECTIONS] != SECTIONS:
        out.append("sections out of order: " + ", ".join(found))
    syntax = text.split("\n## Examples")[0]
    block = re.search(r"```text\n(.*?)```", syntax, flags=re.S)
    if not block:
        out.append("no plain-text syntax block (```text ... ```) in Syntax")
    else:
        b = block.group(1)
        style = re.search(r"^# (fix|compute) (\S+) command", text, flags=re.M)
        first = b.splitlines()[0] if b.strip() else ""
        if kind == "command":  # "STYLE args ... :pre", no ID or group
            style = re.search(r"^# (\S+) command", text, flags=re.M)
            if not (style and first.startswith(style.group(1) + " ") and first.endswith(":pre")):
                out.append("the plain-text block must start with 'STYLE ... :pre'")
            if ":ulb,l" not in b or ":ule" not in b:
                out.append("the plain-text block needs the argument list (:ulb,l ... :ule)")
        else:
            if not (style and first.startswith("%s ID group-ID %s" % (kind, style.group(2)))
                    and first.endswith(":pre")):
                out.append("the plain-text block must start with '%s ID group-ID STYLE ... :pre'"
                           % kind)
            if "ID, group-ID are documented in" not in b or ":ulb,l" not in b or ":ule" not in b:
                out.append("the plain-text block needs the argument list (:ulb,l ... :ule)")
        out += keyword_drift(syntax[:block.start()], b)
    restart = text.split("## Restart info")[-1].split("\n## Restrictions")[0]
    modify = "fix_modify" if kind == "fix" else "compute_modify"
    needles = [(modify, modify), ("`start` and `stop`", "run start/stop"),
               ("minimize", "minimize")]
    if kind == "command":
        needles = [("restart file", "a restart file keeps")]
    for needle, what in needles:
        if needle not in restart:
            out.append("Restart info does not say what %s does" % what)
    if "## Validity" in text:
        out += validity_problems(text)
    refs = text.split("## References")[-1] if "## References" in text else ""
    if "Machado" not in refs:
        out.append("References do not cite the paper (Machado et al. 2014)")
    return out


def main():
    if len(sys.argv) != 2:
        sys.stderr.write("usage: check_docs.py SOURCE_DIR\n")
        return 2
    pages = sorted(glob.glob(os.path.join(sys.argv[1], "doc", "fix_*.md")) +
                   glob.glob(os.path.join(sys.argv[1], "doc", "compute_*.md")) +
                   glob.glob(os.path.join(sys.argv[1], "doc", "command_*.md")))
    if not pages:
        print("ERROR: no style page under %s/doc" % sys.argv[1])
        return 1
    bad = 0
    for p in pages:
        for msg in problems(p):
            print("ERROR: %s: %s" % (os.path.relpath(p, sys.argv[1]), msg))
            bad += 1
    commands = sorted(p for p in glob.glob(os.path.join(sys.argv[1], "doc", "post", "*.md"))
                      if os.path.basename(p) not in ("input.md", "library.md"))
    commands += glob.glob(os.path.join(sys.argv[1], "doc", "deck_bearing.md"))
    bad_commands = 0
    for p in commands:
        for msg in command_page_problems(p):
            print("ERROR: %s: %s" % (os.path.relpath(p, sys.argv[1]), msg))
            bad_commands += 1
    print("doc check: %d style page(s), %d problem(s); %d command page(s), %d problem(s)"
          % (len(pages), bad, len(commands), bad_commands))
    return 1 if bad or bad_commands else 0


if __name__ == "__main__":
    sys.exit(main())
