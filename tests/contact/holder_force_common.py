"""Shared checks of the force-controlled holder tests (holder_force_*.prm).

A plate lies on the fixed flat die (data/flat_die.tool, z = 0); a flat holder
(data/flat_holder.tool, z = 0.5, normal -z) on its top face is
force-controlled along a = (0, 0, -1). Its position z is one more unknown
whose equation is sum_pairs a . P = F(t) (doc/theory_contact.md). At every converged
increment:
  * the holder force along a equals F(t): the equation is part of the Newton
    system, converged to 1e-12 of the force scale, so 1e-8 relative leaves
    4 orders for round-off;
  * the die carries the same force (equilibrium of the plate, which has no
    other support along z): 1e-8 relative;
  * the holder moves down and never leaves the plate (its translation is
    negative from the first increment on).
Without a tool named punch there is no punch_force.csv; draw_in.csv has a
row per tools.csv row; the default thickness-profile travels (15, 20 mm) lie
beyond the punch travel: no thickness file.
"""
import csv
import glob
import os
import sys


def check(output, force, extra=None):
    with open(output + "/tools.csv") as f:
        rows = [row for row in csv.DictReader(f) if float(row["load"]) > 0]
    failures = 0
    for row in rows:
        t = float(row["load"])
        expected = force(t)
        holder = -float(row["holder_Fz"])  # a . P with a = (0, 0, -1)
        die = float(row["die_Fz"])
        errors = (abs(holder - expected) / expected,
                  abs(die - expected) / expected)
        ok = max(errors) <= 1e-8 and float(row["holder_uz"]) < 0
        if extra is not None:
            ok = extra(row, t) and ok
        failures += not ok
        print("%s t %.4f F(t) %.9g holder %.12g die %.12g rel. errors %.1e %.1e"
              " holder uz %.6e" % ("ok  " if ok else "FAIL", t, expected, holder,
                                   die, errors[0], errors[1],
                                   float(row["holder_uz"])))
    if len(rows) < 5:
        print("FAIL: only %d increments" % len(rows))
        failures += 1
    with open(output + "/draw_in.csv") as f:
        draw_in = [row for row in csv.DictReader(f) if float(row["punch_travel_mm"]) > 0]
    tables_ok = (not os.path.exists(output + "/punch_force.csv")
                 and len(draw_in) == len(rows)
                 and not glob.glob(output + "/thickness_*"))
    failures += not tables_ok
    print("%s no punch_force.csv, %d draw_in.csv rows, no thickness file"
          % ("ok  " if tables_ok else "FAIL", len(draw_in)))
    return failures
