#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The case table of a sweep (doc/case_table.md): a CSV file, one column per deck variable, one
row per case. Read by inputs/bearing_6208/in.sweep (partitions), inputs/cluster/sweep_slurm.sh
(job array) and the study commands (studies/); stdlib only.

  cases.py grid NAME=V1,V2,... [NAME=...] [--output FILE]   every combination, one row each
  cases.py check TABLE                          validate; print the number of cases
  cases.py tasks TABLE K                        number of array tasks of K cases each
  cases.py args TABLE INDEX                     case INDEX (0-based): its folder, then NAME VALUE
                                                lines (what the launcher passes with -var)
  cases.py sweep-table TABLE ROOT               write ROOT/sweep_cases.csv (the cases, their folders)
  cases.py sweep-init ...  / sweep-common ...   in.sweep's helpers (LIGGGHTS include files)

A bad table is an error naming the file, line and column: 'ERROR: ...' on stderr, exit 2."""
import argparse
import csv
import io
import math
import os
import re
import sys

NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")
# Set by the launchers for every case, never by the table.
RESERVED = {"out", "root", "here", "resume", "catalog", "bearing_deck", "cases", "case",
            "sizes", "ncases"}
DECK_INDEX = re.compile(r"\bvariable\s+([A-Za-z_][A-Za-z0-9_]*)\s+index\b")
UNSET = "__unset__"
NUMBER_CHARS = re.compile(r"[0-9+\-.eE]+\Z")


class TableError(Exception):
    pass


def read_table(path, sweep_copy=False):
    """(names, rows, lines): the header's variable names, the rows (lists of cells) and the line
    number of each row. Comment lines (#) and blank lines are skipped. `sweep_copy`: the table
    is ROOT/sweep_cases.csv, whose first column 'case' is the folder."""
    try:
        with open(path, newline="") as fh:
            text = fh.read()
    except OSError as e:
        raise TableError(f"case table {path}: cannot be read ({e.strerror})")
    header, rows, lines = None, [], []
    reader = csv.reader(io.StringIO(text), skipinitialspace=True, strict=True)
    try:
        for cells in reader:
            line = reader.line_num
            if not cells or all(not c.strip() for c in cells) or cells[0].lstrip().startswith("#"):
                continue
            cells = [c.strip() for c in cells]
            if header is None:
                header = cells
                if sweep_copy and header[:1] == ["case"]:
                    check_header(path, line, header[1:])
                else:
                    check_header(path, line, header)
                continue
            if len(cells) != len(header):
                raise TableError(f"{path}:{line}: {len(cells)} cells, the header has "
                                 f"{len(header)} ({', '.join(header)}): every row gives one "
                                 f"value per column")
            for col, (name, cell) in enumerate(zip(header, cells), 1):
                if not cell:
                    raise TableError(f"{path}:{line}: column {col} ({name}) is empty: give a value")
                if '"' in cell or any(ord(ch) < 32 for ch in cell):
                    raise TableError(f"{path}:{line}: column {col} ({name}): the value {cell!r} "
                                     f"holds a double quote or a control character")
            rows.append(cells)
            lines.append(line)
    except csv.Error as e:
        raise TableError(f"{path}:{reader.line_num}: not valid CSV ({e})")
    if header is None:
        raise TableError(f"case table {path} is empty: expected a header line of deck variable "
                         f"names (e.g. F,size) and one row per case")
    if not rows:
        raise TableError(f"case table {path} has a header ({', '.join(header)}) but no case: "
                         f"add one row per case")
    folders = {}
    for cells, line in zip(rows, lines):
        f = cells[0] if sweep_copy else folder_of(header, cells)
        if f in folders:
            raise TableError(f"{path}:{line}: the case repeats line {folders[f]} (both go to the "
                             f"folder {f})")
        folders[f] = line
    return header, rows, lines


def check_header(path, line, header):
    seen = {}
    for col, name in enumerate(header, 1):
        if not NAME.match(name):
            hint = " (is the header line missing?)" if re.match(r"[-+.0-9]", name) else ""
            raise TableError(f"{path}:{line}: column {col} header {name!r} is not a deck variable "
                             f"name (letters, digits, _; not starting with a digit){hint}")
        if name in RESERVED:
            raise TableError(f"{path}:{line}: column {col} header {name!r} is set by the sweep "
                             f"itself, not by the table (reserved: {', '.join(sorted(RESERVED))})")
        if name in seen:
            raise TableError(f"{path}:{line}: column {col} repeats column {seen[name]} ({name})")
        seen[name] = col


def folder_of(names, cells):
    """The case's folder: NAME_VALUE pairs joined by '_' (size_0.5, F_100_size_0.5); characters
    other than letters, digits and ._+- in a value become '-'."""
    return "_".join(f"{n}_{re.sub(r'[^A-Za-z0-9._+-]', '-', v)}" for n, v in zip(names, cells))


def label_of(names, cells):
    return ",".join(f"{n}={v}" for n, v in zip(names, cells))


def deck_variables(deck, catalog):
    """The index-style variables of the deck and of the bearing catalog entries (and the deck's
    catalog_NAME copies): what a case resets to its default unless the sweep fixes it."""
    found = set()
    if catalog == "auto":  # as in.bearing: $OHMDEM_CATALOG, else the catalog of this tree
        catalog = os.environ.get("OHMDEM_CATALOG") or os.path.join(
            os.path.dirname(os.path.abspath(__file__)), "..", "bearings")
    files = [deck]
    if catalog and os.path.isdir(catalog):
        files += [os.path.join(catalog, f) for f in sorted(os.listdir(catalog))
                  if "." not in f and os.path.isfile(os.path.join(catalog, f))]
    for i, path in enumerate(files):
        try:
            text = open(path).read()
        except OSError as e:
            raise TableError(f"deck file {path}: cannot be read ({e.strerror})")
        names = set(DECK_INDEX.findall(text))
        found |= names
        if i > 0:
            found |= {"catalog_" + n for n in names}
    return found


def check_columns_in_deck(path, names, known, deck):
    for col, n in enumerate(names, 1):
        if n not in known:
            raise TableError(f"{path}: column {col} ({n}) is not a variable of the deck {deck} "
                             f"(nor of the bearing catalog): a typo would run the same case "
                             f"for every row")


def deck_forms(deck):
    """{NAME: FORM} of the deck's check_variables lines (doc/command_check_variables.md), the
    forms the deck checks its variables against before LIGGGHTS parses them."""
    try:
        text = open(deck).read()
    except OSError as e:
        raise TableError(f"deck file {deck}: cannot be read ({e.strerror})")
    forms, line = {}, ""
    for raw in text.splitlines() + [""]:
        body = raw.split("#", 1)[0].rstrip()
        if line or body.lstrip().startswith("check_variables"):
            line += " " + body.rstrip("&")
            if body.endswith("&"):
                continue
            words = line.split()[1:]
            forms.update(zip(words[0::2], words[1::2]))
            line = ""
    return forms


def form_mismatch(form, value):
    """"" when the cell has the deck variable's form, else what was expected and given: the
    forms of src_fix/lib/writers/variable_forms.h, for a table's cells (a v_NAME cell names a
    variable the sweep defines: its form alone is checked)."""
    def plain(v, more=""):
        return bool(v) and v[0] not in "\"'" and not any(
            ord(c) < 32 or c in " \x7f" + more for c in v)
    def number(v):
        if not NUMBER_CHARS.match(v):
            return False
        try:
            return math.isfinite(float(v))
        except ValueError:
            return False
    names = {"number": "a number", "v_equal": "v_NAME of an equal-style variable",
             "path": "a path without blanks or control characters",
             "folder": "a folder without blanks, control characters, '*' or '%'",
             "word": "a word without blanks or control characters"}
    alts = form.split("|")
    for a in alts:
        if ((a == "number" and number(value)) or (a == "path" and plain(value)) or
                (a == "folder" and plain(value, "*%")) or (a == "word" and plain(value)) or
                (a == "v_equal" and re.fullmatch(r"v_[A-Za-z_][A-Za-z0-9_]*", value)) or
                (a not in names and value == a)):
            return ""
    said = [names.get(a, a) for a in alts]
    expected = said[0] if len(said) == 1 else ", ".join(said[:-1]) + " or " + said[-1]
    return f"expected {expected}, got {value!r}"


def cell_problems(path, names, rows, lines, forms):
    """[(row index, message)] for the cells that lack their deck variable's form."""
    out = []
    for k, (cells, line) in enumerate(zip(rows, lines)):
        for col, (name, cell) in enumerate(zip(names, cells), 1):
            bad = form_mismatch(forms[name], cell) if name in forms else ""
            if bad:
                out.append((k, f"{path}:{line}: column {col} ({name}): deck variable {name}: "
                               f"{bad}"))
                break
    return out


def write_atomic(path, text):
    """Every partition writes the same file: a whole file, never a half-written one."""
    tmp = f"{path}.{os.getpid()}.tmp"
    with open(tmp, "w") as fh:
        fh.write(text)
    os.replace(tmp, path)


def lmp_error(lmp, message, command):
    """A LIGGGHTS include that prints the error, then stops the run with an unknown command."""
    write_atomic(lmp, f"print 'ERROR: {message.replace(chr(39), '`')}'\n{command}\n")


def cmd_grid(a):
    names, values = [], []
    for spec in a.specs:
        name, eq, vals = spec.partition("=")
        if not eq or not vals:
            raise TableError(f"grid: {spec!r}: expected NAME=V1,V2,... (e.g. F=100,200)")
        if not NAME.match(name) or name in RESERVED:
            raise TableError(f"grid: {spec!r}: {name!r} is not a deck variable name "
                             f"(letters, digits, _; not starting with a digit; not reserved)")
        if name in names:
            raise TableError(f"grid: {name} given twice")
        cells = [v.strip() for v in vals.split(",")]
        if any(not v for v in cells):
            raise TableError(f"grid: {spec!r}: an empty value")
        names.append(name)
        values.append(cells)
    rows = [[]]
    for cells in values:  # the first name varies slowest
        rows = [r + [v] for r in rows for v in cells]
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(names)
    w.writerows(rows)
    if a.output:
        write_atomic(a.output, buf.getvalue())
        read_table(a.output)  # the same checks as every launcher
    else:
        sys.stdout.write(buf.getvalue())


def cmd_check(a):
    names, rows, lines = read_table(a.table)
    if a.deck:
        check_columns_in_deck(a.table, names, deck_variables(a.deck, a.catalog), a.deck)
        bad = cell_problems(a.table, names, rows, lines, deck_forms(a.deck))
        if bad:
            raise TableError("; ".join(m for _, m in bad) +
                             f" ({len(bad)} of {len(rows)} cases; the others are valid)")
    print(len(rows))


def parse_per_task(text):
    try:
        k = int(text)
    except ValueError:
        k = 0
    if k < 1 or str(k) != text.strip():
        raise TableError(f"K (cases per task) must be a whole number >= 1, got {text!r}")
    return k


def cmd_tasks(a):
    _, rows, _ = read_table(a.table)
    k = parse_per_task(a.per_task)
    print((len(rows) + k - 1) // k)


def cmd_args(a):
    names, rows, _ = read_table(a.table)
    i = int(a.index) if re.fullmatch(r"[0-9]+", a.index) else -1
    if not 0 <= i < len(rows):
        raise TableError(f"{a.table}: case index {a.index} out of range: the table has {len(rows)} "
                         f"cases (0..{len(rows) - 1})")
    print(folder_of(names, rows[i]))
    print(label_of(names, rows[i]))
    for n, v in zip(names, rows[i]):
        print(f"{n} {v}")


def sweep_table_path(root):
    return os.path.join(root, "sweep_cases.csv")


def write_sweep_table(root, names, rows):
    """ROOT/sweep_cases.csv: the cases with their folders; ohmdem-post collect ROOT reads it."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["case"] + names)
    for cells in rows:
        w.writerow([folder_of(names, cells)] + cells)
    write_atomic(sweep_table_path(root), buf.getvalue())


def cmd_sweep_table(a):
    names, rows, _ = read_table(a.table)
    write_sweep_table(a.root, names, rows)


def cmd_sweep_init(a):
    """in.sweep, before the first case: the table (-var cases FILE, or -var sizes "..." as
    before), its copy ROOT/sweep_cases.csv, and an include defining the case counter and
    probing which deck variables the sweep fixes for every case."""
    try:
        if a.table != "none":
            names, rows, lines = read_table(a.table)
            source = a.table
        else:
            sizes = a.sizes
            if a.ncases not in ("0", str(len(sizes))):
                raise TableError(f"-var ncases {a.ncases} but -var sizes has {len(sizes)} values "
                                 f"({' '.join(sizes)})")
            names, rows = ["size"], [[s] for s in sizes]
            lines = list(range(1, len(rows) + 1))
            source = "-var sizes"
        known = deck_variables(a.deck, a.catalog)
        check_columns_in_deck(source, names, known, a.deck)
        # A cell without its variable's form fails its case alone (the others run).
        invalid = cell_problems(source, names, rows, lines, deck_forms(a.deck))
    except TableError as e:
        print(f"ERROR: {e}", file=sys.stderr)
        lmp_error(a.lmp, str(e), "sweep_case_table_invalid")
        return
    write_sweep_table(a.root, names, rows)
    write_atomic(os.path.join(a.root, ".sweep_invalid"),
                 "".join(f"{k + 1}\t{m}\n" for k, m in invalid))
    for _, m in invalid:
        print(f"ERROR: {m}: that case fails, the others run", file=sys.stderr)
    probe = sorted(known - set(names) - RESERVED)
    out = [f"variable sweep_n equal {len(rows)}",
           "variable case universe " + " ".join(str(i) for i in range(1, len(rows) + 1))]
    # A deck variable defined before this (-var, in.sweep's defaults) keeps its value for every
    # case; the others read __unset__ here, and sweep-common writes the cases' includes that
    # reset them before each case.
    out += [f"variable {n} index {UNSET}" for n in probe]
    # deck_files exec: the values reach cases.py as arguments, never a shell
    out.append(f"deck_files exec /usr/bin/python3 {os.path.abspath(__file__)} sweep-common v_root "
               + " ".join(f"{n}=${{{n}}}" for n in probe))
    write_atomic(a.lmp, "\n".join(out) + "\n")


def cmd_sweep_common(a):
    """After the probe: the deck variables still __unset__ are the ones each case resets. Writes
    ROOT/.sweep_case_K.lmp for every case K (1-based): delete those variables (the previous
    case's values; the deck's defaults come back), set the row's, the folder `out`, the label
    and the defect size. All at once: a helper program costs a process start."""
    unset = []
    for i, tok in enumerate(a.pairs):
        m = re.match(r"([A-Za-z_][A-Za-z0-9_]*)=(.*)\Z", tok)
        if m and m.group(2) == UNSET and (i + 1 == len(a.pairs) or "=" in a.pairs[i + 1]):
            unset.append(m.group(1))
    names, rows, _ = read_table(sweep_table_path(a.root), sweep_copy=True)
    names = names[1:]  # the 'case' column is the folder
    invalid = {}
    try:
        for line in open(os.path.join(a.root, ".sweep_invalid")):
            k, _, why = line.rstrip("\n").partition("\t")
            invalid[int(k)] = why
    except OSError:
        pass
    for k, row in enumerate(rows, 1):
        folder, cells = row[0], row[1:]
        out = [f"variable {n} delete" for n in unset]
        for n, v in zip(names, cells):
            out += [f"variable {n} delete", f'variable {n} index "{v}"']
        size = cells[names.index("size")] if "size" in names else 1
        why = invalid.get(k, "").replace('"', "`")
        out += [f"variable out string {os.path.join(a.root, folder)}",
                f'variable case_label string "{label_of(names, cells)}"',
                # the defect size (degrees) for in.sweep's check; 1 without a size column
                f'variable case_size string "{size}"',
                # a cell without its deck variable's form: in.sweep fails the case alone
                f"variable case_invalid string {1 if k in invalid else 0}",
                f'variable case_invalid_why string "{why}"']
        write_atomic(os.path.join(a.root, f".sweep_case_{k}.lmp"), "\n".join(out) + "\n")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="cmd", required=True)
    g = sub.add_parser("grid")
    g.add_argument("specs", nargs="+")
    g.add_argument("--output")
    g.set_defaults(run=cmd_grid)
    c = sub.add_parser("check")
    c.add_argument("table")
    c.add_argument("--deck")
    c.add_argument("--catalog")
    c.set_defaults(run=cmd_check)
    t = sub.add_parser("tasks")
    t.add_argument("table")
    t.add_argument("per_task")
    t.set_defaults(run=cmd_tasks)
    r = sub.add_parser("args")
    r.add_argument("table")
    r.add_argument("index")
    r.set_defaults(run=cmd_args)
    st = sub.add_parser("sweep-table")
    st.add_argument("table")
    st.add_argument("root")
    st.set_defaults(run=cmd_sweep_table)
    si = sub.add_parser("sweep-init")
    si.add_argument("--table", required=True)
    si.add_argument("--sizes", nargs="+", default=[])
    si.add_argument("--ncases", default="0")
    si.add_argument("--root", required=True)
    si.add_argument("--deck", required=True)
    si.add_argument("--catalog", required=True)
    si.add_argument("--lmp", required=True)
    si.set_defaults(run=cmd_sweep_init)
    sc = sub.add_parser("sweep-common")
    sc.add_argument("root")
    sc.add_argument("pairs", nargs="*")
    sc.set_defaults(run=cmd_sweep_common)
    a = p.parse_args()
    try:
        a.run(a)
    except TableError as e:
        print(f"ERROR: {e}", file=sys.stderr)
        sys.exit(2)


if __name__ == "__main__":
    main()
