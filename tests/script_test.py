"""What the script tests (tests/<label>/*_test.py, tests/cad/square_cup_step.py)
share: their command line, a fresh work directory, running deepdraw, and
comparing CSV tables of two runs column by column; the check scripts of the
prm tests read tables with rows().

    import script_test  (after sys.path.insert of the tests directory)
"""
import argparse
import csv
import pathlib
import shutil
import subprocess
import sys
import time


def start(description, extra_arguments=()):
    """Parses --deepdraw, --source-dir, --work-dir (and extra_arguments:
    (flag, keyword arguments of add_argument) pairs); empties the work
    directory and links prm/ there to the sources' prm/, which the shipped
    parameter files include relative to where deepdraw is started.
    Returns (arguments, source directory, work directory)."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--deepdraw", required=True)
    parser.add_argument("--source-dir", required=True)
    parser.add_argument("--work-dir", required=True)
    for flag, options in extra_arguments:
        parser.add_argument(flag, **options)
    args = parser.parse_args()
    args.deepdraw = str(pathlib.Path(args.deepdraw).resolve())
    source = pathlib.Path(args.source_dir).resolve()
    work = pathlib.Path(args.work_dir)
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    (work / "prm").symlink_to(source / "prm", target_is_directory=True)
    return args, source, work


def run(command, cwd, tail=None):
    """Runs command in cwd, prints its output (the last `tail` characters)
    and returns it; exits the test if the command fails."""
    print("running:", " ".join(command), flush=True)
    result = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    print(result.stdout if tail is None else result.stdout[-tail:])
    if result.returncode != 0:
        sys.exit("FAILED: exit code %d" % result.returncode)
    return result.stdout


def table(path):
    """(header, rows of floats) of a CSV table."""
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in row] for row in rows[1:] if row]


def compare_columns(expected, actual, tables, tolerance, looser=None):
    """Each column of each of `tables` in `actual` within `tolerance` (or
    looser[column]) of the largest magnitude of that column in `expected`:
    two runs that converge the same increments by different paths to a
    Newton tolerance. Prints every column; returns the failures."""
    looser = looser or {}
    failures = []
    for name in tables:
        header, reference = table(expected / name)
        header_actual, values = table(actual / name)
        if header_actual != header or len(values) != len(reference):
            failures.append("%s: other columns or rows" % name)
            continue
        for j, column in enumerate(header):
            scale = max(abs(row[j]) for row in reference) or 1.0
            difference = max(abs(a[j] - e[j])
                             for a, e in zip(values, reference)) / scale
            allowed = looser.get(column, tolerance)
            ok = difference <= allowed
            print("%s %-20s %-16s %.2e (tolerance %.0e)"
                  % ("ok  " if ok else "FAIL", name, column, difference,
                     allowed))
            if not ok:
                failures.append("%s %s differs by %.3g relative"
                                % (name, column, difference))
    return failures


def rows(path):
    """The rows of a CSV table as {column: float} (the check scripts of the
    prm tests import this module too)."""
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()}
                for row in csv.DictReader(f)]


def compare_tables(expected_directory, actual_directory, names, tolerance):
    """Every column of the tables `names` of two runs: the largest
    difference relative to the column's largest magnitude must be at most
    tolerance. Prints each column; returns (failures, largest relative
    difference)."""
    failures = []
    worst = 0.0
    for name in names:
        header, expected = table(pathlib.Path(expected_directory) / name)
        header_actual, actual = table(pathlib.Path(actual_directory) / name)
        if header_actual != header or len(actual) != len(expected):
            failures.append("%s: %d rows %s, expected %d rows %s"
                            % (name, len(actual), header_actual,
                               len(expected), header))
            continue
        for j, column in enumerate(header):
            scale = max(abs(row[j]) for row in expected) or 1.0
            deviation = max(abs(a[j] - e[j]) for a, e in zip(actual, expected))
            worst = max(worst, deviation / scale)
            ok = deviation <= tolerance * scale
            print("%s %-22s %-16s largest difference %.3e of %.4g over %d "
                  "rows (tolerance %.0e relative)"
                  % ("ok  " if ok else "FAIL", name, column, deviation / scale,
                     scale, len(expected), tolerance))
            if not ok:
                failures.append("%s %s differs by %.3g relative"
                                % (name, column, deviation / scale))
    return failures, worst


def comparable_table(path, skipped=("symbolic_analyses",)):
    """The cells of a CSV table as text, without the wall times (*_s) and
    the columns `skipped` (the orderings counted in statistics.csv depend
    on the process's history, D97): two runs of one model must agree in
    these byte for byte."""
    with open(path) as f:
        rows = list(csv.reader(f))
    keep = [j for j, name in enumerate(rows[0])
            if not name.endswith("_s") and name not in skipped]
    return [[row[j] for j in keep] for row in rows]


def snapshot(directory):
    """{file name: bytes} of a directory, to show a refused run left it
    as it was."""
    return {p.name: p.read_bytes()
            for p in sorted(pathlib.Path(directory).iterdir())}


def finish(failures):
    """Prints each failure and exits 1 if there is one, else PASSED."""
    for failure in failures:
        print("FAILED:", failure)
    if failures:
        sys.exit(1)
    print("PASSED")


def write_case(source, work, prm):
    """Copies the prm `prm` (a path under the sources) to
    work/case/process.prm with its tool files found in tests/contact/data
    from there; returns its text."""
    (work / "case").mkdir(exist_ok=True)
    text = (source / prm).read_text().replace(
        "../contact/data", str(source / "tests" / "contact" / "data"))
    (work / "case" / "process.prm").write_text(text)
    return text


def run_and_resume(deepdraw, work, resumed_at):
    """Runs case/process.prm into work/full, copies that to work/resumed and
    resumes it there with --resume. Returns the failures: the resumed run
    must begin at load `resumed_at` and write every CSV table of the
    uninterrupted run (comparable_table)."""
    run([deepdraw, "case/process.prm", "--output-directory", "full"], work)
    shutil.copytree(work / "full", work / "resumed")
    log = run([deepdraw, "case/process.prm", "--output-directory", "resumed",
               "--resume"], work)
    failures = []
    if "resumed at load %s" % resumed_at not in log:
        failures.append("the resumed run did not begin at load %s"
                        % resumed_at)
    return failures + same_tables(work / "full", work / "resumed")


def stop_after(process, output, increments, signal_number):
    """Sends the signal to `process` once output/statistics.csv has
    `increments` rows (exits FAILED if the run ends first or takes over two
    minutes); returns its exit code, stdout and stderr."""
    statistics = pathlib.Path(output) / "statistics.csv"
    deadline = time.time() + 120
    while not statistics.exists() or \
            len(statistics.read_text().splitlines()) - 1 < increments:
        if process.poll() is not None or time.time() > deadline:
            sys.exit("FAILED: the run ended before increment %d" % increments)
        time.sleep(0.002)
    process.send_signal(signal_number)
    out, err = process.communicate(timeout=120)
    return process.returncode, out, err


def same_tables(expected, actual, what="the uninterrupted run"):
    """Every CSV table of the directory `expected` must be in `actual` with
    the same cells (comparable_table); returns the failures."""
    failures = []
    for table in sorted(p.name for p in pathlib.Path(expected).glob("*.csv")):
        same = comparable_table(pathlib.Path(expected) / table) == \
            comparable_table(pathlib.Path(actual) / table)
        print("%s %s" % ("same" if same else "DIFFERENT", table))
        if not same:
            failures.append("%s differs from %s" % (table, what))
    return failures


def write_linear_solver_case(work, name, included, settings, extra=""):
    """Writes work/name: an include of the prm `included`, then `extra`,
    then the `Linear solver` settings (name, value pairs); returns name (the
    solver tests run one model with several solvers)."""
    text = "include %s\n%s" % (included, extra)
    text += "subsection Linear solver\n%send\n" % "".join(
        "  set %s = %s\n" % item for item in settings)
    (work / name).write_text(text)
    return name


def close_tables(expected, actual, what, relative=1e-12,
                 skipped=("symbolic_analyses",)):
    """As same_tables, but for runs on different machines (D190): the text
    cells equal, and the numbers equal to `relative` of the larger, or
    their difference below `relative` times the largest magnitude in the
    table (round-off: Newton residuals of 1e-17, reactions of 1e-16 N of a
    frictionless plate). Returns the failures."""
    failures = []
    for table in sorted(p.name for p in pathlib.Path(expected).glob("*.csv")):
        a = comparable_table(pathlib.Path(expected) / table, skipped)
        b = comparable_table(pathlib.Path(actual) / table, skipped)
        same = len(a) == len(b) and a[0] == b[0] and \
            all(len(ra) == len(rb) for ra, rb in zip(a, b))
        worst = 0.
        if same:
            largest = 0.
            for row in a[1:] + b[1:]:
                for v in row:
                    try:
                        largest = max(largest, abs(float(v)))
                    except ValueError:
                        pass
            floor = relative * largest
            for ra, rb in zip(a[1:], b[1:]):
                for x, y in zip(ra, rb):
                    if x == y:
                        continue
                    try:
                        fx, fy = float(x), float(y)
                    except ValueError:
                        same = False
                        continue
                    allowed = max(relative * max(abs(fx), abs(fy)), floor)
                    worst = max(worst, abs(fx - fy) / allowed
                                if allowed > 0 else float("inf"))
            same = same and worst <= 1.
        print("%s %s (largest difference %.2g of the allowed)"
              % ("close" if same else "DIFFERENT", table, worst))
        if not same:
            failures.append("%s differs from %s" % (table, what))
    return failures


class Checks:
    """The checks of a check.py: each prints its value against the
    expected one and keeps the failures."""

    def __init__(self):
        self.failures = []

    def check(self, what, value, expected, tolerance, relative=True):
        scale = abs(expected) if relative and expected != 0 else 1.0
        error = abs(value - expected) / scale
        ok = error <= tolerance
        print("%-50s %.10g (expected %.10g, error %.2e)%s"
              % (what, value, expected, error, "" if ok else "  FAILED"))
        if not ok:
            self.failures.append(what)

    def exit_code(self):
        for failure in self.failures:
            print("FAILED:", failure)
        return 1 if self.failures else 0


def csv_rows(path):
    """The rows of a CSV table as {column: float}."""
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()}
                for row in csv.DictReader(f)]
