"""Checks of press_lift_press.prm, a process of three stages (D101).

Closed form: the elastic quarter plate (E = 71000 MPa, A = 2 x 2 mm,
T = 0.5 mm) between frictionless flat tools is in uniaxial stress, so a
force F shortens it by delta = T F / (E A) (small strain).
 1 'press' (0 < t <= 1): the force-controlled holder carries 30 N and the
   die the same (equations of the Newton system, converged to 1e-12:
   1e-9 relative); the holder stands at -delta(30) = -5.2817e-5 mm,
   2e-3 relative (measured 1.3e-4: large-strain and hypoelastic terms of
   order of the strain, 1e-4).
 2 'lift' (1 < t <= 2): the holder takes no part: no force on either tool
   and none through the bottom face (held in z from this stage on),
   |F| <= 1e-9 N; the holder stays where it stood (its translation at t = 1,
   to the 10 digits of the output); the plate is stress-free again, so its
   volume is back to A T = 2 mm^3 (1e-9 relative; 1.4e-4 below it while
   pressed).
 3 'press again' (2 < t <= 3): the holder under displacement control moves
   from where it stood, by 2e-4 (t - 2) mm: its translation is exact (1e-9
   relative), and the force is E A / T (delta(30) + 2e-4 (t - 2)), 2e-3
   relative (measured 5.6e-4, the strain is 5e-4); the die carries the same
   force (1e-9 relative).
The load stepping of each stage: 0.5 in the first two, the third's own
0.25: the increments end at 0.5, 1, 1.5, 2, 2.25, 2.5, 2.75, 3.
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from script_test import Checks, csv_rows as rows  # noqa: E402

E, A, T = 71000.0, 4.0, 0.5
STIFFNESS = E * A / T
DELTA_1 = 30.0 / STIFFNESS


def main(output):
    checks = Checks()
    check = checks.check
    failures = checks.failures

    tools = rows(output + "/tools.csv")
    loads = [row["load"] for row in tools][1:]
    if loads != [0.5, 1, 1.5, 2, 2.25, 2.5, 2.75, 3]:
        failures.append("increments end at %s" % loads)
    lifted = {row["load"]: row for row in tools}[1.0]["holder_uz"]
    volumes = {row["load"]: row["sheet_volume_mm3"]
               for row in rows(output + "/statistics.csv")}
    bottom = {row["load"]: row["zmin_Fz"]
              for row in rows(output + "/reactions.csv")}
    for row in tools:
        t = row["load"]
        if 0 < t <= 1:
            check("t = %g: holder force" % t, -row["holder_Fz"], 30, 1e-9)
            check("t = %g: die force" % t, row["die_Fz"], 30, 1e-9)
            check("t = %g: holder position" % t, row["holder_uz"], -DELTA_1,
                  2e-3)
        elif 1 < t <= 2:
            for name in ("holder_Fz", "die_Fz"):
                check("t = %g: %s" % (t, name), row[name], 0, 1e-9, False)
            check("t = %g: bottom face force" % t, bottom[t], 0, 1e-9, False)
            check("t = %g: holder position" % t, row["holder_uz"], lifted,
                  1e-9)
            check("t = %g: volume" % t, volumes[t], A * T, 1e-9)
        elif t > 2:
            check("t = %g: holder position" % t, row["holder_uz"],
                  lifted - 2e-4 * (t - 2), 1e-9)
            force = STIFFNESS * (DELTA_1 + 2e-4 * (t - 2))
            check("t = %g: holder force" % t, -row["holder_Fz"], force, 2e-3)
            check("t = %g: die force" % t, row["die_Fz"], -row["holder_Fz"],
                  1e-9)
    return checks.exit_code()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
