"""Checks of stage_newton_settings.prm, a stage's own Newton settings (D208).

Independent expectations:
- The bar is elastic and its strain at most 4e-4, so the problem is linear
  up to terms of the order of the strain increment, 2.5e-5 (the geometric
  terms): the extrapolation predictor (the last increment scaled) leaves a
  relative residual of that order (measured 2e-5 to 7e-5), below the
  prm's tolerances of 1e-3 and above stage 3's 1e-9; one Newton
  correction takes it to round-off (1e-15). So, for every increment but
  the first of each stage (which starts from the tangent predictor, its
  solve counted as iteration 1): stage 1 ends at the predictor (0
  iterations), stage 2 takes its minimum 1, stage 3 the 1 its tolerance
  needs, stage 4 its minimum 3.
- The extra iterations leave the answer alone: the force on the pulled
  face is E A u / L in uniaxial stress (E = 206000 MPa, the quarter
  section A = 1 mm^2, L = 10 mm), 1e-3 relative (stage 1 ends within the
  1e-3 tolerance; measured 4.4e-4 at t = 4, growing with the strain).
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from script_test import Checks, csv_rows as rows  # noqa: E402

E, A, L = 206000.0, 1.0, 10.0
EXPECTED = {1: 0, 2: 1, 3: 1, 4: 3}   # Newton iterations per increment, by stage


def stage_of(load):
    """Stage k runs from t = k - 1 to k."""
    return int(load - 1e-9) + 1


def main(output):
    checks = Checks()
    failures = checks.failures
    statistics = rows(output + "/statistics.csv")
    if len(statistics) != 16:
        failures.append("%d increments, expected 16 of 0.25" % len(statistics))
    for row in statistics:
        stage = stage_of(row["load"])
        if abs(row["load"] - (stage - 1) - 0.25) < 1e-9:
            continue  # the first of its stage: the tangent predictor
        iterations = int(row["newton_iterations"])
        ok = iterations == EXPECTED[stage]
        print("t = %g (stage %d): %d Newton iterations, expected %d%s"
              % (row["load"], stage, iterations, EXPECTED[stage],
                 "" if ok else "  FAILED"))
        if not ok:
            failures.append("t = %g: %d iterations" % (row["load"],
                                                       iterations))
    for row in rows(output + "/reactions.csv"):
        t = row["load"]
        if t > 0:
            checks.check("t = %g: force on the pulled face" % t,
                         row["xmax_Fx"], E * A * 1e-3 * t / L, 1e-3)
    return checks.exit_code()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
