"""Checks of wall_rotation.prm: a rigid rotation of the plate into a
vertical wall leaves its surface strains zero.

Expected, at every increment (formability.csv) and at every column and
surface (fld_0.5mm.csv, fld_1mm.csv): eps1 = eps2 = 0 and the thickness
strain 0, the margin eps1*(0) = 0.16 of the FLC (100 % of it), every column
in the zone 'insufficient stretch' (eps1 < 0.02, eps2 > -0.02). Tolerance
1e-14: the prescribed rotation puts the surface vertices where cos and sin
of the angle put them (1e-16 relative), and the strains of a rigid motion
are those of C = I to round-off (measured 4.4e-16).
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from script_test import rows  # noqa: E402

TOLERANCE = 1e-14
COLUMNS = 12


def main(output):
    failures = []
    largest = 0.0
    table = rows(output + "/formability.csv")
    if len(table) != 11:
        failures.append("formability.csv has %d rows, expected 11" % len(table))
    for row in table:
        for name in ("eps1", "eps2", "thickness_strain"):
            largest = max(largest, abs(row[name]))
        if abs(row["worst_margin"] - 0.16) > TOLERANCE:
            failures.append("t = %g: worst margin %.12g" % (row["load"],
                                                          row["worst_margin"]))
        if row["insufficient_stretch"] != COLUMNS:
            failures.append("t = %g: %g columns of insufficient stretch"
                            % (row["load"], row["insufficient_stretch"]))
    for label in ("0.5", "1"):
        points = rows(output + "/fld_%smm.csv" % label)
        if len(points) != 3 * COLUMNS:
            failures.append("fld_%smm.csv has %d points" % (label, len(points)))
        for p in points:
            largest = max(largest, abs(p["eps1"]), abs(p["eps2"]))
            if abs(p["margin"] - 0.16) > TOLERANCE or p["zone"] != 4:
                failures.append("fld_%smm.csv: margin %.12g, zone %g"
                                % (label, p["margin"], p["zone"]))
    print("largest |strain| of a rigid rotation into the wall: %.3g "
          "(tolerance %.0e)" % (largest, TOLERANCE))
    if largest > TOLERANCE:
        failures.append("a strain of %.3g" % largest)
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
