#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""What every study and benchmark driver starts with (studies/README.md): where the decks and
the bearing catalog are, which ohmdem and ohmdem-post to run, the bearing's data read from its
catalog file, running a deck on one process or on MPI partitions, and writing case tables.

It works in the source tree (executables in build/) and in an install (this folder is
PREFIX/share/ohmdem/studies, the executables PREFIX/bin). $OHMDEM, $POST and $OHMDEM_CATALOG
override what it finds. Run as a program, it prints the same settings as shell assignments for
the shell drivers of bench/:   eval "$(/usr/bin/python3 studies/common.py --shell)"
(main() below lists its other answers).
"""
import csv
import importlib.util
import io
import json
import os
import re
import shlex
import shutil
import subprocess
import sys

STUDIES = os.path.dirname(os.path.abspath(__file__))
# The source tree's root, or PREFIX/share/ohmdem in an install: both hold inputs/.
BASE = os.path.dirname(STUDIES)
INPUTS = os.path.join(BASE, "inputs")
DECK_DIR = os.path.join(INPUTS, "bearing_6208")
BEARING_DECK = os.path.join(DECK_DIR, "in.bearing")
SWEEP_DECK = os.path.join(DECK_DIR, "in.sweep")
CASES_SCRIPT = os.path.join(INPUTS, "cluster", "cases.py")
INSTALLED = os.path.basename(BASE) == "ohmdem" and os.path.basename(
    os.path.dirname(BASE)) == "share"
PREFIX_BIN = os.path.join(os.path.dirname(os.path.dirname(BASE)), "bin") if INSTALLED else None
# doc/ (the committed reports and template banks): PREFIX/share/doc/ohmdem in an install
DOC = os.path.join(os.path.dirname(BASE), "doc", "ohmdem") if INSTALLED else os.path.join(BASE, "doc")
CATALOG = os.environ.get("OHMDEM_CATALOG", os.path.join(INPUTS, "bearings"))
# in.bearing finds the catalog through OHMDEM_CATALOG when run from another folder.
os.environ.setdefault("OHMDEM_CATALOG", CATALOG)
# Open MPI refuses to start as root without these (containers, CI).
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
           "OMPI_MCA_rmaps_base_oversubscribe": "1"}


def executable(name, env_var):
    """$env_var if set; else PREFIX/bin/NAME in an install, build/NAME in the source tree, else
    NAME on PATH; build/NAME when none exists (the failing command then names it)."""
    if os.environ.get(env_var):
        return os.environ[env_var]
    candidates = [os.path.join(BASE, "build", name)]
    if PREFIX_BIN:
        candidates.insert(0, os.path.join(PREFIX_BIN, name))
    for path in candidates:
        if os.access(path, os.X_OK):
            return path
    return shutil.which(name) or candidates[-1]


OHMDEM = executable("ohmdem", "OHMDEM")
POST = executable("ohmdem-post", "POST")

_INDEX = re.compile(r"^\s*variable\s+([A-Za-z0-9_]+)\s+index\s+([^\s#]+)", re.M)


def number(text):
    """An int when the text is a whole number (Nb), else a float, else the text."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def index_variables(path):
    """The `variable NAME index VALUE` lines of a LIGGGHTS input file: {NAME: value}."""
    with open(path) as f:
        return {n: number(v) for n, v in _INDEX.findall(f.read())}


class Bearing:
    """A catalog entry (doc/bearing_catalog.md), read from its file: Nb, Db, Dext, Dinn, and
    the groove radii Rcext, Rcinn (the deck's defaults when the entry omits them)."""

    def __init__(self, name="machado2014", catalog=None):
        self.name = name
        self.path = os.path.join(catalog or CATALOG, name)
        v = index_variables(self.path)
        if "Dpw" in v and "Nb" in v and "Db" in v and "Dext" not in v:  # the deck's races
            v["Dext"], v["Dinn"] = v["Dpw"] + v["Db"], v["Dpw"] - v["Db"]
        try:
            self.nb, self.db, self.dext, self.dinn = v["Nb"], v["Db"], v["Dext"], v["Dinn"]
        except KeyError as e:
            sys.exit(f"ERROR: bearing catalog file {self.path}: no variable {e.args[0]}")
        self.rcext = v.get("Rcext", self.db * 6.65 / 12.6)  # in.bearing's Rcext_default
        self.rcinn = v.get("Rcinn", self.db * 6.55 / 12.6)

    @property
    def pitch(self):
        """Pitch diameter D (m): the mean of the groove-bottom diameters."""
        return (self.dext + self.dinn) / 2

    def bpfi_order(self):
        """Inner-race defect frequency over the shaft frequency: Nb/2 (1 + d/D)."""
        return self.nb / 2 * (1 + self.db / self.pitch)

    def bpfo_order(self):
        """Outer-race defect frequency over the shaft frequency: Nb/2 (1 - d/D)."""
        return self.nb / 2 * (1 - self.db / self.pitch)

    def cage_speed(self, omega):
        """Orbital speed of the balls for a fixed outer ring (rad/s): omega/2 (1 - d/D)."""
        return omega / 2 * (1 - self.db / self.pitch)


def deck_defaults():
    """The bearing deck's own index defaults (E, nu, rho, gamma, I, ...)."""
    return index_variables(BEARING_DECK)


def _cases_module():
    spec = importlib.util.spec_from_file_location("ohmdem_cases", CASES_SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def case_table(path, names, rows):
    """Writes a case table (doc/case_table.md) and checks it as every launcher does
    (inputs/cluster/cases.py)."""
    cases = _cases_module()
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(names)
    w.writerows([[str(c) for c in r] for r in rows])
    cases.write_atomic(path, buf.getvalue())
    try:
        cases.read_table(path)
    except cases.TableError as e:
        sys.exit(f"ERROR: {e}")
    return path


def grid_table(path, columns):
    """Every combination of [(name, [values])], the first name varying slowest (cases.py grid)."""
    rows = [[]]
    for _, values in columns:
        rows = [r + [v] for r in rows for v in values]
    return case_table(path, [n for n, _ in columns], rows)


def variables(values):
    """-var NAME VALUE arguments, in the order given."""
    args = []
    for k, v in values.items():
        args += ["-var", k, str(v)]
    return args


def deck_command(deck, args, partitions=1):
    """ohmdem -in DECK ARGS, on one process or on P MPI partitions of one process each."""
    if partitions > 1:
        return (["mpirun", "-np", str(partitions), OHMDEM, "-partition", f"{partitions}x1",
                 "-in", deck] + args)
    return [OHMDEM, "-in", deck] + args


def sweep_command(root, cases, values, log, partitions=1):
    """The partition sweep in.sweep over a case table: ROOT/<case folder> per row. Run it in
    ROOT (run(..., cwd=root)): the partitions share their case counter through a file in the
    working folder (LIGGGHTS' uloop variable), which two sweeps in one folder would share."""
    args = ["-var", "here", DECK_DIR, "-var", "bearing_deck", BEARING_DECK, "-var", "root", root,
            "-var", "cases", cases]
    return deck_command(SWEEP_DECK, args + variables(values) + ["-log", log, "-screen", "none"],
                        partitions)


def run(cmd, log=None, who="study", mpi=None, cwd=None):
    """Runs cmd (its output to LOG when given) in CWD; stops the study with the command on
    failure. mpi: the root flags for mpirun (default: when cmd starts with mpirun)."""
    env = dict(os.environ, **MPI_ENV) if (mpi if mpi is not None else cmd[0] == "mpirun") else None
    if log:
        with open(log, "w") as f:
            r = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, env=env, cwd=cwd)
    else:
        r = subprocess.run(cmd, env=env, cwd=cwd)
    if r.returncode != 0:
        sys.exit(f"{who}: failed ({r.returncode}): {' '.join(cmd)}"
                 + (f"; see {log}" if log else ""))


def finished(run_dir):
    """Whether the run in RUN_DIR ended: its run.json is written at the start, so a run stopped
    halfway (killed, a full disk) has one too, with another status, and must be run again
    rather than read as a cached run."""
    try:
        with open(os.path.join(run_dir, "run.json")) as f:
            return json.load(f).get("status") == "finished"
    except (OSError, ValueError):
        return False


def post(args, who="study", allow_fail=False):
    """ohmdem-post ARGS, its output captured (a CompletedProcess)."""
    r = subprocess.run([POST] + args, capture_output=True, text=True)
    if r.returncode != 0 and not allow_fail:
        sys.exit(f"{who}: ohmdem-post {' '.join(args)} failed: {r.stderr.strip()}")
    return r


def post_to(path, args, who="study"):
    """ohmdem-post ARGS with its standard output written to PATH (as `> PATH`)."""
    with open(path, "w") as f:
        f.write(post(args, who).stdout)


def write_csv(path, rows, quoted=()):
    """The study's rows (dicts with the same keys) as CSV: None empty, floats to 6 digits; the
    `quoted` columns (free text) in double quotes, theirs turned into single ones."""
    cols = list(rows[0].keys())

    def cell(c, v):
        if c in quoted:
            return '"' + str(v).replace('"', "'") + '"'
        if v is None:
            return ""
        return f"{v:.6g}" if isinstance(v, float) else str(v)

    with open(path, "w") as f:
        f.write(",".join(cols) + "\n")
        for r in rows:
            f.write(",".join(cell(c, r[c]) for c in cols) + "\n")


def interval_text(low, high):
    """[low, high] to 3 digits, 'open' for a missing high; '-' without an interval."""
    if low is None:
        return "-"
    return f"[{low:.3g}, " + ("open" if high is None else f"{high:.3g}") + "]"


def read_signal(path, t0=None):
    """signal.txt as {column: numpy array}, only the rows with time > t0 when given."""
    import numpy as np
    with open(path) as f:
        names = f.readline().lstrip("#").split()
    a = np.loadtxt(path)
    s = {n: a[:, i] for i, n in enumerate(names)}
    if t0 is None:
        return s
    keep = s["time"] > t0
    return {n: v[keep] for n, v in s.items()}


def source_commit():
    """The source tree's commit (12 hex digits), "with uncommitted changes" when the code the
    studies run (post/, src_fix/, app/, inputs/, studies/) differs from it; "unknown" outside a
    git checkout (an install)."""
    try:
        head = subprocess.run(["git", "-C", BASE, "rev-parse", "--short=12", "HEAD"],
                              capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", BASE, "status", "--porcelain", "--", "post",
                                "src_fix", "app", "inputs", "studies"], capture_output=True,
                               text=True).stdout.strip()
        return head + (" with uncommitted changes" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def made_at():
    """Where a report comes from, for its first lines: "commit C (YYYY-MM-DD)" (UTC)."""
    import datetime
    return (f"commit {source_commit()} "
            f"({datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d})")


def shell_settings():
    """The settings as POSIX shell assignments (exported)."""
    values = {"OHMDEM": OHMDEM, "POST": POST, "OHMDEM_CATALOG": CATALOG, "OHMDEM_BASE": BASE,
              "OHMDEM_DECKS": DECK_DIR, **MPI_ENV}
    return "".join(f"export {k}={shlex.quote(v)}\n" for k, v in values.items())


def main(argv):
    """--shell: the settings as shell assignments; --cage-speed W: the 6208's ball orbital speed
    at inner speed W (rad/s); --bearing FIELD: a field of the 6208 (nb, db, dext, dinn, pitch)."""
    if argv == ["--shell"]:
        sys.stdout.write(shell_settings())
    elif len(argv) == 2 and argv[0] == "--cage-speed":
        print(repr(Bearing().cage_speed(float(argv[1]))))
    elif len(argv) == 2 and argv[0] == "--bearing" and argv[1] in (
            "nb", "db", "dext", "dinn", "pitch"):
        print(getattr(Bearing(), argv[1]))
    else:
        sys.exit("usage: common.py --shell | --cage-speed OMEGA | --bearing nb|db|dext|dinn|pitch")


if __name__ == "__main__":
    main(sys.argv[1:])
