#!/usr/bin/env python3
"""Points beyond the curve's range (doc/user_guide.md §8.2, D172):
homogeneous_paths.prm (a plate strained along e1 = 0.1 t, e2 = -0.05 t to
t = 1, then e2 = -0.05 to t = 2, then equibiaxially, every point alike) with
the tabulated curve -0.02, 0.14; 0, 0.1; 0.2, 0.2, whose range ends at
e2 = -0.02: the points lie beyond it for 0.4 < t < 2.6, where the curve is
held at 0.14. Closed form (every point alike, the worst point the first
column's bottom):
- formability.csv: beyond_range = 1 exactly where e2 < -0.02; in_range_margin
  the margin limit(e2) - e1 where e2 >= -0.02, 1e300 where no
  point lies within the range; the earlier columns as for any curve;
- fld_1mm.csv and fld_2.5mm.csv: beyond_range = 1 at every point
  (e2 = -0.05 and -0.025);
- the summary line: first crossed at t = 1.5 (e1 = 0.14 on the held value
  at t = 1.4; the first increment above it),
  beyond the curve's range (eps2 = -0.05, eps2/eps1 = -0.3333, range
  -0.02 <= eps2 <= 0.2), and within its range first crossed at t = 2.75
  (e2 = -0.0125: limit 0.125 < e1 = 0.2375; t = 2.5 still has e2 =
  -0.025);
- a study of this prm (deepdraw --study) has the columns
  flc_first_crossing_mm = 1.5, flc_first_crossing_beyond_range = 1,
  flc_first_crossing_in_range_mm = 2.75, flc_least_margin and
  flc_least_margin_in_range = the last rows' margins (D174).
Tolerance 1e-12 (the tables print 10 significant digits of short decimals).

    beyond_range_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import csv
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402
from script_test import rows, run  # noqa: E402

LARGEST = 1e300
TOLERANCE = 1e-12


def e1(t):
    return 0.1 * t if t <= 2 else 0.2 + 0.05 * (t - 2)


def e2(t):
    return -0.05 * t if t <= 1 else -0.05 if t <= 2 else -0.05 + 0.05 * (t - 2)


def limit(minor):
    if minor <= -0.02:
        return 0.14
    if minor <= 0:
        return 0.1 - 2. * minor
    return 0.1 + 0.5 * minor


def main():
    args, source, work = script_test.start(__doc__)
    text = (source / "tests" / "formability"
            / "homogeneous_paths.prm").read_text()
    text = text.replace("set Table               = -0.2, 0.26; 0, 0.16; "
                        "0.2, 0.26",
                        "set Table               = -0.02, 0.14; 0, 0.1; "
                        "0.2, 0.2")
    text = text.replace("visualization, forming limits, statistics",
                        "forming limits, statistics")
    prm = work / "beyond_range.prm"
    prm.write_text(text)
    failures = []
    if "0.02, 0.14; 0, 0.1" not in text:
        failures.append("the table of homogeneous_paths.prm was not replaced")

    log = run([args.deepdraw, str(prm), "--output-directory", "run"], work,
              tail=800)
    summary = [line for line in log.splitlines()
               if line.startswith("deepdraw: forming limit")]
    # Every point alike: which one is the worst is round-off.
    place = r"\(X, Y\) = \([0-3]\.5, [0-2]\.5\), (bottom|mid|top) surface"
    expected = ("deepdraw: forming limit first crossed at t = 1\\.5 mm at "
                + place + ", beyond the curve's range \\(eps2 = -0\\.05, "
                "eps2/eps1 = -0\\.3333; the curve is given for -0\\.02 <= "
                "eps2 <= 0\\.2 and only held at its end value beyond\\); "
                "within its range first crossed at t = 2\\.75 mm at " + place
                + "$")
    print("summary:", summary)
    if len(summary) != 1 or not re.match(expected, summary[0]):
        failures.append("the summary is %s, expected '%s'" % (summary,
                                                               expected))

    for row in rows(work / "run" / "formability.csv"):
        t = row["load"]
        beyond = e2(t) < -0.02 - 1e-12
        if row["beyond_range"] != (1 if beyond else 0):
            failures.append("t = %g: beyond_range %g" % (t,
                                                         row["beyond_range"]))
        expected_margin = LARGEST if beyond else limit(e2(t)) - e1(t)
        if abs(row["in_range_margin"] - expected_margin) \
                > TOLERANCE * max(1., abs(expected_margin)):
            failures.append("t = %g: in_range_margin %.12g, expected %.12g"
                            % (t, row["in_range_margin"], expected_margin))
        if abs(row["worst_margin"] - (limit(e2(t)) - e1(t))) > TOLERANCE:
            failures.append("t = %g: worst_margin %.12g" % (t,
                                                            row["worst_margin"]))
    for label in ("1", "2.5"):
        flags = {p["beyond_range"]
                 for p in rows(work / "run" / ("fld_%smm.csv" % label))}
        if flags != {1}:
            failures.append("fld_%smm.csv: beyond_range %s" % (label, flags))

    run([args.deepdraw, str(prm), "--output-directory", "study", "--study",
         "Formability/Safety band = 10"], work, tail=800)
    with open(work / "study" / "study.csv") as f:
        study = list(csv.DictReader(f))
    expected_study = {"flc_first_crossing_mm": 1.5,
                      "flc_first_crossing_beyond_range": 1,
                      "flc_first_crossing_in_range_mm": 2.75,
                      "flc_least_margin": limit(e2(3)) - e1(3),
                      "flc_least_margin_in_range": limit(e2(3)) - e1(3)}
    for name, value in expected_study.items():
        got = study[0].get(name) if study else None
        if not got or abs(float(got) - value) > TOLERANCE:
            failures.append("study.csv: %s = %s, expected %g" % (name, got,
                                                                value))
    script_test.finish(failures)


if __name__ == "__main__":
    main()
