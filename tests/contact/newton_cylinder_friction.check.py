"""Quadratic Newton convergence with frictional contact on a curved tool
(newton_cylinder_friction.prm; issue 4, test 6).

The semismooth Newton method on the Alart-Curnier system converges
quadratically once the contact status (open / stick / slip of every pair) no
longer changes, provided the Jacobian is the exact derivative of the discrete
residual (doc/theory_material.md, doc/theory_contact.md: curvature terms of the cylinder, slip direction,
geometric terms). As in tests/regression/tension_bar.check.py the order is
measured by log r_{k+1} / log r_k >= 1.8 on the relative residuals r of
newton.csv (max of force and contact residual), in the asymptotic range:
  * the contact status did not change from iterate k to iterate k+1
    (newton.csv: contact_changes == 0 on the row of iterate k+1), so the step
    k -> k+1 was a Newton step on one smooth piece of the semismooth system;
  * r_k < 1e-1 (as for the tension bar);
  * r_{k+1} > 1e-11: above the round-off floor of this system, measured at
    1e-13..1e-12 (last iterations of every increment).
All increments must converge without cut-backs, and at least 10 pairs must be
measured. (Increments without any status change at all, contact_changes == 0
in statistics.csv, do not occur: the contact zone grows and the pairs
re-evaluate at the start of every increment; they are listed if any.)
"""
import csv
import math
import sys


def main(output):
    with open(output + "/newton.csv") as f:
        newton = list(csv.DictReader(f))
    with open(output + "/statistics.csv") as f:
        statistics = list(csv.DictReader(f))
    failures = 0
    orders = []
    residual = lambda row: max(float(row["force_residual"]),
                               float(row["contact_residual"]))
    for previous, current in zip(newton, newton[1:]):
        if (previous["increment"], previous["load"]) != (current["increment"],
                                                         current["load"]):
            continue
        r0, r1 = residual(previous), residual(current)
        if float(current["contact_changes"]) == 0 and r0 < 1e-1 and r1 > 1e-11:
            order = math.log(r1) / math.log(r0)
            orders.append(order)
            ok = order >= 1.8
            failures += not ok
            print("%s increment %s iteration %s -> %s: %.2e -> %.2e  log ratio"
                  " %.2f" % ("ok  " if ok else "FAIL", current["increment"],
                             previous["iteration"], current["iteration"], r0,
                             r1, order))
    if len(orders) < 10:
        print("FAIL: only %d asymptotic pairs measured" % len(orders))
        failures += 1
    settled = [row["increment"] for row in statistics
               if float(row["contact_changes"]) == 0]
    print("increments without any contact status change:", settled or "none")
    cut_backs = sum(float(row["cut_backs"]) for row in statistics)
    if cut_backs > 0 or float(statistics[-1]["load"]) != 1.0:
        print("FAIL: %d cut-backs, final load %s" % (cut_backs, statistics[-1]["load"]))
        failures += 1
    print("min order %.2f over %d pairs" % (min(orders) if orders else float("nan"), len(orders)))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main(sys.argv[1])
