"""Checks of press_release.prm, a force release (D150).

The elastic plate pressed by F = 30 N between frictionless flat tools is in
uniaxial stress F / A (press_lift_press.check.py): its volume falls by
(1 - 2 nu) F / (A E) = 3.59e-5 relative (1e-3: terms of order of the strain,
1e-4; measured 4e-5). The
release takes the contact forces of the end of stage 1 over as loads that
fall linearly to zero: at the stage's end no tool takes part, so no tool
carries a force (|F| <= 1e-9 N), and the plate is stress-free, its volume
back to A T = 2 mm^3 (1e-9 relative, as the lift of press_lift_press, which
measured it exactly to the 10 digits of the output). Halfway the loads are
half: the volume change is half that of the pressed plate (linear
elasticity, 1e-3 relative: the change itself is of order of the strain,
1e-4, and the hypoelastic terms change it by as much relative).
The Newton iterations of the release increments are printed (newton.csv):
with the default element (incompatible modes) each converges in at most 4
iterations to 1e-12 (measured 3, D152).
"""
import csv
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from script_test import Checks, csv_rows as rows  # noqa: E402

A, T, E, NU, F = 4.0, 0.5, 71000.0, 0.33, 30.0


def main(output):
    checks = Checks()
    check = checks.check
    failures = checks.failures

    tools = {row["load"]: row for row in rows(output + "/tools.csv")}
    volumes = {row["load"]: row["sheet_volume_mm3"]
               for row in rows(output + "/statistics.csv")}
    if sorted(volumes) != [0.5, 1, 1.25, 1.5, 1.75, 2]:
        failures.append("increments end at %s" % sorted(volumes))
    pressed = A * T - volumes[1.0]
    check("pressed: volume change / A T", pressed / (A * T),
          (1 - 2 * NU) * F / (A * E), 1e-3)
    check("halfway: volume change", A * T - volumes[1.5], pressed / 2, 1e-3)
    check("released: volume", volumes[2.0], A * T, 1e-9)
    for name in ("holder_Fz", "die_Fz"):
        check("released: " + name, tools[2.0][name], 0, 1e-9, False)

    iterations = {}
    with open(output + "/newton.csv") as f:
        for row in csv.DictReader(f):
            if float(row["load"]) > 1:
                print("release: increment %s load %s iteration %s force "
                      "residual %s" % (row["increment"], row["load"],
                                       row["iteration"],
                                       row["force_residual"]))
                iterations[row["load"]] = int(row["iteration"])
    if not iterations or max(iterations.values()) > 4:
        failures.append("release increments took %s Newton iterations"
                        % iterations)
    return checks.exit_code()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
