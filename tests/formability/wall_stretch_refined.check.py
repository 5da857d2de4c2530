"""Checks of wall_stretch_refined.prm: a plate stretched and turned into a
vertical wall, refined in the plane after its first increment.

Expected: formability.csv at every increment and every point of
fld_0.5mm.csv and fld_1mm.csv have eps1 = 0.1 t, eps2 = 0.05 t (the
in-plane stretches of the prescribed map, whatever the rotation) and the
thickness strain -0.15 t; the diagrams list the 18 columns of the refined
mesh (12 - 2 + 8: two footprints refined into four) with 4 columns in each
unit square the refinement split. Tolerance 1e-14: the strains are exact to
round-off on refined meshes (tests/formability/column_strains), and the
expected ones are short decimals that the tables' 10 significant digits
print exactly (measured 1.4e-17).
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from script_test import rows  # noqa: E402

TOLERANCE = 1e-14


def main(output):
    failures = []
    largest = 0.0

    def check(what, value, expected):
        nonlocal largest
        error = abs(value - expected) / max(1.0, abs(expected))
        largest = max(largest, error)
        if error > TOLERANCE:
            failures.append("%s: %.12g, expected %.12g" % (what, value,
                                                          expected))

    table = rows(output + "/formability.csv")
    for row in table:
        t = row["load"]
        check("t = %g: eps1" % t, row["eps1"], 0.1 * t)
        check("t = %g: eps2" % t, row["eps2"], 0.05 * t)
        check("t = %g: thickness strain" % t, row["thickness_strain"],
              -0.15 * t)
    for travel, label in ((0.5, "0.5"), (1.0, "1")):
        points = rows(output + "/fld_%smm.csv" % label)
        if len(points) != 3 * 18:
            failures.append("fld_%smm.csv: %d points, expected 54"
                            % (label, len(points)))
        in_refined = sum(1 for p in points if p["X"] < 2 and p["Y"] < 1)
        if in_refined != 3 * 8:
            failures.append("fld_%smm.csv: %d points in the refined squares, "
                            "expected 24" % (label, in_refined))
        for p in points:
            where = "fld_%smm.csv (%g, %g)" % (label, p["X"], p["Y"])
            check(where + ": eps1", p["eps1"], 0.1 * travel)
            check(where + ": eps2", p["eps2"], 0.05 * travel)
    print("%d rows of formability.csv; largest relative error %.3g "
          "(tolerance %.0e)" % (len(table), largest, TOLERANCE))
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
