#!/usr/bin/env python3
"""The short square cup (tests/regression/square_cup_short.prm: 12 x 12 x 2
elements, 0 -> 3 mm in 0.1 mm increments, residuals to 1e-6) run twice: with
the built-in square-cup tools, and with the same tools written as STEP files
by `deepdraw --write-square-cup-tools` and read back through the Contact
subsection of the shipped prm/square_cup_step.prm (Geometry = cad, doc/
tool_files.md). Punch force, holder force and lift, and the draw-in DX, DY,
DD must agree at every increment to 1e-6 of each column's largest magnitude
(measured: 1.5e-8 for the holder lift, at most 2.9e-9 in the other columns,
see doc/tool_files.md); the run on the STEP tools must report its three
tools as read (faces, patches).

    square_cup_step.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import argparse
import csv
import pathlib
import shutil
import subprocess
import sys

TOLERANCE = 1e-6
TABLES = ("punch_force.csv", "draw_in.csv")


def run(command, cwd):
    print("running:", " ".join(command), flush=True)
    result = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    print(result.stdout)
    if result.returncode != 0:
        sys.exit("FAILED: exit code %d" % result.returncode)
    return result.stdout


def table(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in row] for row in rows[1:] if row]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--deepdraw", required=True)
    parser.add_argument("--source-dir", required=True)
    parser.add_argument("--work-dir", required=True)
    args = parser.parse_args()

    source = pathlib.Path(args.source_dir).resolve()
    work = pathlib.Path(args.work_dir)
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    # square_cup_short.prm includes prm/square_cup.prm relative to the
    # working directory (tests/run_prm_test.py does the same).
    (work / "prm").symlink_to(source / "prm", target_is_directory=True)
    short = source / "tests" / "regression" / "square_cup_short.prm"

    # The tools where prm/square_cup_step.prm expects them: ../square-cup-
    # tools from the prm's directory (here work/run).
    run([args.deepdraw, "--write-square-cup-tools", "square-cup-tools",
         str(short)], work)
    shipped = (source / "prm" / "square_cup_step.prm").read_text()
    start = shipped.index("subsection Contact")
    end = shipped.index("\nend\n", start) + len("\nend\n")
    (work / "run").mkdir()
    (work / "run" / "built_in.prm").write_text("include %s\n" % short)
    (work / "run" / "step.prm").write_text(
        "include %s\n%s" % (short, shipped[start:end]))

    run([args.deepdraw, "run/built_in.prm", "--output-directory", "built_in"],
        work)
    log = run([args.deepdraw, "run/step.prm", "--output-directory", "step"],
              work)

    failures = []
    for name in ("punch", "die", "blank holder"):
        if "tool '%s' from run/../square-cup-tools/" % name not in log:
            failures.append("no report of the STEP tool '%s'" % name)
    for name in TABLES:
        header, expected = table(work / "built_in" / name)
        header_step, actual = table(work / "step" / name)
        if header_step != header or len(actual) != len(expected):
            failures.append("%s: %d rows %s, built-in %d rows %s"
                            % (name, len(actual), header_step, len(expected),
                               header))
            continue
        for j, column in enumerate(header):
            scale = max(abs(row[j]) for row in expected) or 1.0
            deviation = max(abs(a[j] - e[j]) for a, e in zip(actual, expected))
            ok = deviation <= TOLERANCE * scale
            print("%s %-16s %-16s largest difference %.3e of %.4g over %d "
                  "rows (tolerance %.0e relative)"
                  % ("ok  " if ok else "FAIL", name, column, deviation / scale,
                     scale, len(expected), TOLERANCE))
            if not ok:
                failures.append("%s %s differs by %.3g relative"
                                % (name, column, deviation / scale))
    for failure in failures:
        print("FAILED:", failure)
    if failures:
        sys.exit(1)
    print("PASSED")


if __name__ == "__main__":
    main()
