#!/usr/bin/env python3
"""`Linear solver/Reuse factorisation` on a small contact problem (D185):
the short square cup of regression/square_cup_short.prm (12 x 12 x 2, fixed
increments of 0.1 mm to 3 mm, residual tolerances 1e-6, frictional contact
with the three tools and a force-controlled holder), run three times:
- full Newton (every system factorised), the reference;
- with the factorisation reused: some systems must be solved by GMRES with
  kept factors, and the converged increments must agree with the reference
  to the Newton tolerance: every column of punch_force.csv, draw_in.csv,
  tools.csv and the thickness profiles within TOLERANCE of the column's
  largest magnitude (measured 3.0e-6 at most: punch force 3.0e-6, draw-in
  6.1e-7, thickness strain 3.1e-7; the increments are converged to
  residuals of 1e-6, so differences of that order are the solver path),
  but for the columns of LOOSER. The friction forces' x and y sums of die
  and holder differ by 4.3e-4 and the holder's lift by 2.4e-5: a full
  Newton run stops far below its tolerance (quadratic convergence; the
  same run at 1e-8 differs from it by 7.0e-5 and 5.3e-7), an inexact one
  just below it, and the tangential forces of the sticking nodes are the
  least determined by the residual;
- with a forcing term GMRES cannot reach (1e-12 in 1 iteration): every
  attempt falls back to a factorisation, so the run must be the reference
  run byte for byte (every CSV table but the wall times).

    reused_factorization_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402
from script_test import run  # noqa: E402

TOLERANCE = 1e-5
LOOSER = {"die_Fx": 2e-3, "die_Fy": 2e-3, "blank holder_Fx": 2e-3,
          "blank holder_Fy": 2e-3, "holder_z_mm": 1e-4,
          "blank holder_uz": 1e-4}
TABLES = ("punch_force.csv", "draw_in.csv", "tools.csv",
          "thickness_OX_3mm.csv", "thickness_OD_3mm.csv")


def write_prm(source, work, name, settings):
    return script_test.write_linear_solver_case(
        work, name, source / "tests" / "regression" / "square_cup_short.prm",
        settings)


def solver_counts(log):
    match = re.search(r"linear solver: (\d+) factorisations, (\d+) solves "
                      r"with a kept factorisation \((\d+) GMRES", log)
    return tuple(int(g) for g in match.groups()) if match else None


def main():
    args, source, work = script_test.start(__doc__)
    failures = []
    full = write_prm(source, work, "full.prm", [])
    reused = write_prm(source, work, "reused.prm",
                       [("Reuse factorisation", "true")])
    strict = write_prm(source, work, "strict.prm",
                       [("Reuse factorisation", "true"),
                        ("Forcing term", "1e-12"),
                        ("Smallest forcing term", "1e-12"),
                        ("Reuse iterations", "1")])
    run([args.deepdraw, full, "--output-directory", "full"], work, tail=300)
    log = run([args.deepdraw, reused, "--output-directory", "reused"], work,
              tail=300)
    counts = solver_counts(log)
    if counts is None or counts[1] == 0:
        failures.append("no system was solved with a kept factorisation: %s"
                        % (counts,))
    failures += script_test.compare_columns(work / "full", work / "reused",
                                            TABLES, TOLERANCE, LOOSER)

    log = run([args.deepdraw, strict, "--output-directory", "strict"], work,
              tail=300)
    counts = solver_counts(log)
    if counts is None or counts[1] != 0 or counts[2] == 0:
        failures.append("the unreachable forcing term: %s, expected GMRES "
                        "tried and no solve with kept factors" % (counts,))
    failures += script_test.same_tables(work / "full", work / "strict",
                                        "the full Newton run")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
