"""Checks of the tiny sheets (one_cell_sheet.prm, one_row_sheet.prm, D186):
- the run reaches the prm's final load, 5 mm (statistics.csv's last row);
- the forces on the sheet balance: the three tools (tools.csv) and the
  symmetry planes' reactions (reactions.csv, xmin_Fx and ymin_Fy) sum to
  zero in x, y and z, each within 1e-8 of the die force at every increment
  (measured 1.3e-9 and 9.6e-11; the Newton tolerance of 1e-6 is all a run
  promises, the quadratic last step goes far below it). The tools' forces
  come from the contact multipliers, the reactions from the element
  forces: a wrong solve of a tiny system breaks the balance;
- the holder carries its 4900 N to 2e-6 relative (its force equation is
  solved to the Newton tolerance of 1e-6).
"""
import csv
import sys

FINAL_LOAD = 5.0
HOLDER_FORCE = 4900.0


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    output = sys.argv[1]
    failures = []
    statistics = rows(output + "/statistics.csv")
    if abs(float(statistics[-1]["load"]) - FINAL_LOAD) > 1e-12:
        failures.append("stopped at load %s, not %g"
                        % (statistics[-1]["load"], FINAL_LOAD))
    names = ("punch", "die", "blank holder")
    worst_balance = 0.0
    for t, r in zip(rows(output + "/tools.csv"),
                    rows(output + "/reactions.csv")):
        if float(t["load"]) == 0:
            continue
        die = abs(float(t["die_Fz"]))
        balance = (sum(float(t[n + "_Fx"]) for n in names) + float(r["xmin_Fx"]),
                   sum(float(t[n + "_Fy"]) for n in names) + float(r["ymin_Fy"]),
                   sum(float(t[n + "_Fz"]) for n in names))
        worst_balance = max([worst_balance] + [abs(b) / die for b in balance])
    print("force balance: %.2e of the die force" % worst_balance)
    if worst_balance > 1e-8:
        failures.append("force balance off by %.3g of the die force"
                        % worst_balance)
    punch = [r for r in rows(output + "/punch_force.csv")
             if float(r["punch_travel_mm"]) > 0]
    worst_holder = max(abs(float(r["holder_force_N"]) / HOLDER_FORCE - 1)
                       for r in punch)
    print("holder force: %.2e relative" % worst_holder)
    if worst_holder > 2e-6:
        failures.append("holder force off by %.3g relative" % worst_holder)
    for failure in failures:
        print("FAIL " + failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
