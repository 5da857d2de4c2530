"""Helpers of the study checks (tests/study/*.check.py): study.csv and the
CSV files of one run, read independently of deepdraw's own reader."""
import csv
import pathlib
import sys

failures = []


def check(what, ok, detail=""):
    print(("  ok   " if ok else "  FAIL ") + what + (": " + detail if detail else ""))
    if not ok:
        failures.append(what)


def close(what, actual, expected, rel=1e-9, abs_tol=0.0):
    ok = actual is not None and expected is not None and \
        abs(actual - expected) <= max(rel * abs(expected), abs_tol)
    check(what, ok, "%r vs %r" % (actual, expected))


def finish():
    if failures:
        sys.exit("FAILED: %d check(s): %s" % (len(failures), "; ".join(failures)))
    print("all checks passed")


def read_study(output):
    with open(pathlib.Path(output) / "study.csv", newline="") as f:
        return list(csv.DictReader(f))


def number(row, column):
    text = row[column]
    return float(text) if text != "" else None


def read_table(path):
    """A deepdraw CSV file as a list of dicts of floats; None if missing."""
    path = pathlib.Path(path)
    if not path.exists():
        return None
    with open(path, newline="") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def row_at(table, travel):
    rows = [r for r in table if abs(r["punch_travel_mm"] - travel) <= 1e-9 * max(1, travel)]
    return rows[0] if len(rows) == 1 else None


def peak(path):
    """Smallest thickness strain of a profile file and its s0 (the first)."""
    table = read_table(path)
    best = min(table, key=lambda r: r["thickness_strain"])
    return best["thickness_strain"], best["s0_mm"]


def run_values(folder, travel, draw_in=("DX", "DY", "DD")):
    """What study.csv should hold at a travel, from a run's own files."""
    folder = pathlib.Path(folder)
    label = ("%.10g" % travel)
    values = {}
    values["punch_force_N"] = row_at(read_table(folder / "punch_force.csv"), travel)["punch_force_N"]
    draw = row_at(read_table(folder / "draw_in.csv"), travel)
    for name in draw_in:
        values[name + "_mm"] = draw[name + "_mm"]
    for line in ("OX", "OD"):
        strain, s0 = peak(folder / ("thickness_%s_%smm.csv" % (line, label)))
        values[line + "_thinning"] = strain
        values[line + "_thinning_s0_mm"] = s0
    return {k + "_" + label + "mm": v for k, v in values.items()}


def cost(folder):
    """increments, Newton iterations, cut-backs from a run's statistics.csv."""
    stats = read_table(pathlib.Path(folder) / "statistics.csv")
    return (len(stats), sum(r["newton_iterations"] for r in stats),
            sum(r["cut_backs"] for r in stats))
