#!/usr/bin/env python3
"""`Linear solver/Factorisation precision = single` on a small contact
problem (D226): the short square cup of regression/square_cup_short.prm
(12 x 12 x 2, fixed increments of 0.1 mm to 3 mm, residual tolerances
1e-6, frictional contact with the three tools and a force-controlled
holder), run three times:
- double precision (the default on a sheet this small), the reference;
- single-precision factors, each solve refined by GMRES to 1e-3: every
  increment after the first must factorise in single precision (one or
  more factorisations per increment, none redone in double), and the
  converged increments must agree with the reference to the Newton
  tolerance 1e-6: every column of punch_force.csv, draw_in.csv, tools.csv
  and the thickness profiles within 1e-6 of the column's largest magnitude
  (two runs that converge the same increments by different solver paths
  may differ by that much; measured 1.7e-8 at most, the die's friction
  force, because these increments converge far below the tolerance);
- with a refinement tolerance GMRES cannot reach (1e-12 in 1 iteration):
  every single-precision factorisation must be redone in double, so the
  run must be the reference run byte for byte (every CSV table but the wall
  times and the analyses, which count the single-precision instance's).

    single_precision_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402
from script_test import run  # noqa: E402

TOLERANCE = 1e-6
TABLES = ("punch_force.csv", "draw_in.csv", "tools.csv",
          "thickness_OX_3mm.csv", "thickness_OD_3mm.csv")
INCREMENTS = 30  # 0.1 mm to 3 mm


def write_prm(source, work, name, settings):
    return script_test.write_linear_solver_case(
        work, name, source / "tests" / "regression" / "square_cup_short.prm",
        settings)


def single_counts(log):
    match = re.search(r"linear solver: (\d+) factorisations in single "
                      r"precision, refined by GMRES; (\d+) systems "
                      r"factorised again in double", log)
    return tuple(int(g) for g in match.groups()) if match else None


def main():
    args, source, work = script_test.start(__doc__)
    failures = []
    double = write_prm(source, work, "double.prm",
                       [("Factorisation precision", "double")])
    single = write_prm(source, work, "single.prm",
                       [("Factorisation precision", "single")])
    strict = write_prm(source, work, "strict.prm",
                       [("Factorisation precision", "single"),
                        ("Single precision tolerance", "1e-12"),
                        ("Reuse iterations", "1")])
    log = run([args.deepdraw, double, "--output-directory", "double"], work,
              tail=300)
    if single_counts(log) is not None:
        failures.append("double precision reported single-precision "
                        "factorisations")
    log = run([args.deepdraw, single, "--output-directory", "single"], work,
              tail=300)
    counts = single_counts(log)
    print("single precision: %s factorisations, %s redone in double"
          % (counts or ("none", "-")))
    if counts is None or counts[0] < INCREMENTS - 1 or counts[1] != 0:
        failures.append("single precision: %s, expected at least %d "
                        "factorisations in single precision and none "
                        "redone" % (counts, INCREMENTS - 1))
    failures += script_test.compare_columns(work / "double", work / "single",
                                            TABLES, TOLERANCE)

    log = run([args.deepdraw, strict, "--output-directory", "strict"], work,
              tail=300)
    counts = single_counts(log)
    if counts is None or counts[0] == 0 or counts[1] != counts[0]:
        failures.append("the unreachable refinement tolerance: %s, expected "
                        "every single-precision factorisation redone in "
                        "double" % (counts,))
    failures += script_test.same_tables(work / "double", work / "strict",
                                        "the double-precision run")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
