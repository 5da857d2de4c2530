"""Checks of homogeneous_paths.prm: the post-processor "forming limits" on a
plate stretched homogeneously along a non-proportional path.

Closed form: every surface of every column has the logarithmic strains of
the prescribed map, e1(t), e2(t) (homogeneous_paths.prm), the thickness
strain -(e1 + e2) (volume kept), the margin eps1*(e2) - e1 to the tabulated
FLC eps1* = 0.16 - e2/2 (e2 <= 0; 0.16 + e2/2 above), its percent of eps1*,
and the zone of doc/theory_formability.md §5 with the default thresholds.
The strain path (segments of 0.005 major strain, every increment here) has
the ratio d e2 / d e1 of its stage: -1/2, 0, 1; the least and the largest
over the path so far. All 12 columns are in the expected zone.
Tolerances: the strains are exact to round-off (tests/formability/
column_strains) and every expected strain and margin here is a short
decimal, which the tables' 10 significant digits print exactly: 1e-13
(measured 2.5e-15, the round-off of exp and log in the prescribed map and
the strains). The margin in percent is printed to 10 significant digits, whose rounding
is up to 5e-10 relative: 5e-10 (measured 8.8e-11).
The VTU files hold the four fields of every surface.
"""
import glob
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from script_test import rows  # noqa: E402

TOLERANCE = 1e-13
PERCENT_TOLERANCE = 5e-10
COLUMNS = 12


def e1(t):
    return 0.1 * t if t <= 2 else 0.2 + 0.05 * (t - 2)


def e2(t):
    return -0.05 * t if t <= 1 else -0.05 if t <= 2 else -0.05 + 0.05 * (t - 2)


def limit(minor):
    return 0.16 - 0.5 * minor if minor <= 0 else 0.16 + 0.5 * minor


def zone(major, minor):
    """doc/theory_formability.md §5, the default thresholds: safe 0,
    marginal 1, split 2, thinning 3, insufficient stretch 4, wrinkling
    tendency 5."""
    margin = limit(minor) - major
    thickness = -(major + minor)
    if margin <= 0:
        return 2
    if 100 * margin / limit(minor) < 10:
        return 1
    if thickness < -0.25:
        return 3
    if minor <= -0.02 and thickness > 0:
        return 5
    if major < 0.02 and minor > -0.02:
        return 4
    return 0


def stage_ratio(t):
    return -0.5 if t <= 1 else 0.0 if t <= 2 else 1.0


def main(output):
    failures = []
    worst = {TOLERANCE: 0.0, PERCENT_TOLERANCE: 0.0}

    def check(what, value, expected, tolerance=TOLERANCE):
        error = abs(value - expected) / max(1.0, abs(expected))
        worst[tolerance] = max(worst[tolerance], error)
        if error > tolerance:
            failures.append("%s: %.12g, expected %.12g" % (what, value,
                                                          expected))

    table = rows(output + "/formability.csv")
    loads = [row["load"] for row in table]
    if loads != [0.25 * k for k in range(13)]:
        failures.append("formability.csv rows at %s" % loads)
    zones = ["safe", "marginal", "split", "thinning", "insufficient_stretch",
             "wrinkling_tendency"]
    for row in table:
        t = row["load"]
        major, minor = e1(t), e2(t)
        expected_margin = limit(minor) - major
        check("t = %g: eps1" % t, row["eps1"], major)
        check("t = %g: eps2" % t, row["eps2"], minor)
        check("t = %g: thickness strain" % t, row["thickness_strain"],
              -(major + minor))
        check("t = %g: worst margin" % t, row["worst_margin"], expected_margin)
        check("t = %g: worst margin %%" % t, row["worst_margin_percent"],
              100 * expected_margin / limit(minor), PERCENT_TOLERANCE)
        if row["surface"] not in (0, 1, 2):
            failures.append("t = %g: surface %g" % (t, row["surface"]))
        # Before the first segment the ratios are 0 (doc/user_guide.md §8.2).
        ratios = ([stage_ratio(t)] * 3 if t > 0 else [0.0] * 3)
        least = min(stage_ratio(s / 4) for s in range(1, int(4 * t) + 1)) \
            if t > 0 else 0.0
        largest = max(stage_ratio(s / 4) for s in range(1, int(4 * t) + 1)) \
            if t > 0 else 0.0
        check("t = %g: path ratio" % t, row["path_ratio"], ratios[0])
        check("t = %g: least path ratio" % t, row["path_ratio_min"], least)
        check("t = %g: largest path ratio" % t, row["path_ratio_max"], largest)
        counts = [row[name] for name in zones]
        expected_counts = [0] * 6
        expected_counts[zone(major, minor)] = COLUMNS
        if counts != expected_counts:
            failures.append("t = %g: columns per zone %s, expected %s"
                            % (t, counts, expected_counts))
    print("formability.csv: %d rows checked, first row in the split zone at "
          "t = %s" % (len(table), next((r["load"] for r in table
                                        if r["split"] == COLUMNS), None)))

    for travel, label in ((1.0, "1"), (2.5, "2.5")):
        points = rows(output + "/fld_%smm.csv" % label)
        centres = sorted((p["X"], p["Y"], p["surface"]) for p in points)
        expected_centres = sorted((x + 0.5, y + 0.5, s) for x in range(4)
                                  for y in range(3) for s in range(3))
        if centres != expected_centres:
            failures.append("fld_%smm.csv: the points are not every column's "
                            "centre and surface" % label)
        major, minor = e1(travel), e2(travel)
        for p in points:
            where = "fld_%smm.csv (%g, %g, %g)" % (label, p["X"], p["Y"],
                                                   p["surface"])
            check(where + ": eps1", p["eps1"], major)
            check(where + ": eps2", p["eps2"], minor)
            check(where + ": margin", p["margin"], limit(minor) - major)
            if p["zone"] != zone(major, minor):
                failures.append(where + ": zone %g" % p["zone"])
        print("fld_%smm.csv: %d points checked" % (label, len(points)))

    print("largest error %.2g (tolerance %.0e), in %% of the limit %.2g "
          "relative (tolerance %.0e)" % (worst[TOLERANCE], TOLERANCE,
                                          worst[PERCENT_TOLERANCE],
                                          PERCENT_TOLERANCE))

    vtu = sorted(glob.glob(output + "/solution-*.vtu"))
    with open(vtu[-1], "rb") as f:
        header = f.read()
    for field in ("major_strain", "minor_strain", "flc_margin", "fld_zone"):
        for surface in ("bottom", "mid", "top"):
            name = ('Name="%s_%s"' % (field, surface)).encode()
            if name not in header:
                failures.append("%s lacks the field %s_%s" % (vtu[-1], field,
                                                              surface))
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
