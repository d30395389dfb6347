#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The post library's layers, checked (ctest post.layers).

usage: check_layers.py POST_DIR LAYER... [--shared FOLDER...]
       (lowest layer first: core io dsp bearing report cli)

Every file of POST_DIR/<layer>/ may include, among the project's headers, only headers of its
own layer or of a layer listed before it, written from the post root ("dsp/spectrum.h"): never
"../x.h", never a bare "x.h". A --shared FOLDER is a kernel folder of src_fix/lib that the post
library shares with the engine (catalog: the bearing catalog reader); it sits below every layer.
Only the last layer (the command line) names command-line flags: the library names its settings
("{input.column}", core/error.h), in its messages and its comments alike, and every setting a
message names has its flag in cli/setting_flags.cpp (when POST_DIR has it). Prints one line per
offending include, flag or setting and exits 1; prints "post layers: ok" otherwise.
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
# a flag ("--rate") in a string literal or a comment (a decrement, "--it;", is code)
STRING = re.compile(r'"(?:[^"\\\n]|\\.)*"')
FLAG = re.compile(r'(?<![\w-])--[a-z][a-z-]*')
SETTING = re.compile(r'\{([a-z_]+\.[a-z_]+)\}')
MAPPED = re.compile(r'\{"([a-z_]+\.[a-z_]+)",\s*"--')


def flags_named(text):
    """(line number, flag) of each flag in the string literals and comments of `text`."""
    for line_no, line in enumerate(text.split('\n'), 1):
        code, _, comment = line.partition('//')
        for part in STRING.findall(code) + [comment]:
            for m in FLAG.finditer(part):
                yield line_no, m.group(0)


def settings_named(text):
    """(line number, setting) of each "{group.field}" in the string literals of `text`."""
    for line_no, line in enumerate(text.split('\n'), 1):
        for literal in STRING.findall(line.partition('//')[0]):
            for m in SETTING.finditer(literal):
                yield line_no, m.group(1)


def problems(post_dir, order, shared=()):
    rank = {layer: i for i, layer in enumerate(order)}
    rank.update({folder: -1 for folder in shared})
    found = []
    flags_of = os.path.join(post_dir, order[-1], 'setting_flags.cpp')
    mapped = None
    if os.path.isfile(flags_of):
        with open(flags_of, encoding='utf-8') as f:
            mapped = set(MAPPED.findall(f.read()))
    for entry in sorted(os.listdir(post_dir)):
        folder = os.path.join(post_dir, entry)
        if not os.path.isdir(folder):
            if entry.endswith(('.h', '.cpp')):
                found.append(f'{entry}: a source file outside the layers ({", ".join(order)})')
            continue
        if entry not in rank:
            found.append(f'{entry}/: a folder that is not a layer ({", ".join(order)})')
            continue
        for root, _, files in os.walk(folder):
            for name in sorted(files):
                if not name.endswith(('.h', '.cpp')):
                    continue
                path = os.path.join(root, name)
                shown = os.path.relpath(path, post_dir)
                with open(path, encoding='utf-8') as f:
                    text = f.read()
                if entry != order[-1]:
                    for line_no, flag in flags_named(text):
                        found.append(f'{shown}:{line_no}: names the flag {flag}: a library file '
                                     f'names its setting ("{{group.field}}", core/error.h)')
                    for line_no, key in settings_named(text) if mapped is not None else ():
                        if key not in mapped:
                            found.append(f'{shown}:{line_no}: the setting {{{key}}} has no flag in '
                                         f'{os.path.relpath(flags_of, post_dir)}')
                for line_no, inc in ((text.count('\n', 0, m.start()) + 1, m.group(1))
                                     for m in INCLUDE.finditer(text)):
                    where = f'{shown}:{line_no}: #include "{inc}"'
                    if inc.startswith('../') or '/' not in inc:
                        found.append(f'{where}: include from the post root ("dsp/spectrum.h")')
                        continue
                    target = inc.split('/')[0]
                    if target not in rank:
                        found.append(f'{where}: "{target}" is not a layer')
                    elif rank[target] > rank[entry]:
                        found.append(f'{where}: {entry} may not include {target} '
                                     f'(a lower layer cannot include a higher one: '
                                     f'{" < ".join(order)})')
    return found


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    args = sys.argv[2:]
    cut = args.index('--shared') if '--shared' in args else len(args)
    found = problems(sys.argv[1], args[:cut], args[cut + 1:])
    for p in found:
        print(p)
    if found:
        print(f'post layers: {len(found)} problem(s)')
        return 1
    print('post layers: ok')
    return 0


if __name__ == '__main__':
    sys.exit(main())
