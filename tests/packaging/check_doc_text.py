#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The user documentation's text: every relative link of README.md, CHANGELOG.md and doc/**/*.md
leads to a file of the tree (and a #anchor of a Markdown file to one of its headings), and no
page carries a session or issue number ("session 12", "issue 26": the history is the commit
log's and CHANGELOG.md's, by version).

    check_doc_text.py SOURCE_DIR
    check_doc_text.py --self-test

EXEMPT holds the text that other work owns until it moves it: today the diagnose section of
doc/ohmdem-post.md (from its "## diagnose" heading to the file's end).
"""
import glob
import os
import re
import sys
import tempfile

HISTORY = re.compile(r"\b(session|issue)s? [0-9]", re.I)
EXEMPT = {"doc/ohmdem-post.md": "## diagnose"}
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")


def slug(heading):
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    h = re.sub(r"`", "", heading.strip().lower())
    h = re.sub(r"[^\w\- ]", "", h)
    return h.replace(" ", "-")


def anchors(path):
    text = open(path, encoding="utf-8").read()
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    seen, out = {}, set()
    for h in re.findall(r"^#{1,6} (.+?)\s*$", text, flags=re.M):
        s = slug(h)
        n = seen.get(s, 0)
        out.add(s if n == 0 else f"{s}-{n}")
        seen[s] = n + 1
    return out


def pages(root):
    out = [os.path.join(root, n) for n in ("README.md", "CHANGELOG.md")
           if os.path.exists(os.path.join(root, n))]
    return out + sorted(glob.glob(os.path.join(root, "doc", "**", "*.md"), recursive=True))


def problems(root):
    out = []
    for p in pages(root):
        rel = os.path.relpath(p, root)
        text = open(p, encoding="utf-8").read()
        checked = text.split("\n" + EXEMPT[rel])[0] if rel in EXEMPT else text
        for n, line in enumerate(checked.splitlines(), 1):
            m = HISTORY.search(line)
            if m:
                out.append(f"{rel}:{n}: a history mark '{m.group(0)}...' (the commit log's)")
        for n, line in enumerate(re.sub(r"```.*?```", lambda m: "\n" * m.group(0).count("\n"),
                                        text, flags=re.S).splitlines(), 1):
            for target in LINK.findall(line):
                if re.match(r"^[a-z]+:", target):  # http:, https:, mailto:
                    continue
                path, _, anchor = target.partition("#")
                dest = os.path.normpath(os.path.join(os.path.dirname(p), path)) if path else p
                if not os.path.exists(dest):
                    out.append(f"{rel}:{n}: link to {target}: no such file")
                elif anchor and dest.endswith(".md") and anchor not in anchors(dest):
                    out.append(f"{rel}:{n}: link to {target}: no heading '{anchor}' there")
    return out


def self_test():
    with tempfile.TemporaryDirectory() as d:
        os.makedirs(os.path.join(d, "doc", "post"))
        with open(os.path.join(d, "README.md"), "w") as f:
            f.write("# Top\n\n## Two words\n\n[ok](doc/a.md#the-heading) [self](#two-words) "
                    "[gone](doc/none.md) [bad anchor](doc/a.md#nowhere)\n"
                    "As measured in session 12.\n[web](https://example.org)\n")
        with open(os.path.join(d, "doc", "a.md"), "w") as f:
            f.write("# The heading\n\nFixed in issue 26.\n\n## diagnose\n")
        with open(os.path.join(d, "doc", "ohmdem-post.md"), "w") as f:
            f.write("# x\n\nclean\n\n## diagnose\n\nsession 30 (exempt)\n")
        found = problems(d)
    expect = ["README.md:5: link to doc/none.md: no such file",
              "README.md:5: link to doc/a.md#nowhere: no heading 'nowhere' there",
              "README.md:6: a history mark 'session 1", "doc/a.md:3: a history mark 'issue 2"]
    missing = [e for e in expect if not any(f.startswith(e) for f in found)]
    if missing or len(found) != len(expect):
        print("found:\n  " + "\n  ".join(found))
        print("doc text self-test: not found: " + "; ".join(missing))
        return 1
    print("doc text self-test: every planted problem found")
    return 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if len(sys.argv) != 2:
        sys.stderr.write("usage: check_doc_text.py SOURCE_DIR | --self-test\n")
        return 2
    found = problems(sys.argv[1])
    for f in found:
        print("ERROR: " + f)
    print(f"doc text: {len(pages(sys.argv[1]))} page(s), {len(found)} problem(s)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
