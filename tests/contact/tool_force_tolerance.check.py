"""Holder force of tool_force_tolerance.prm.

At every converged increment the blank holder's force must be the prescribed
4900 N to Newton/Tool force tolerance = 1e-6 relative; punch_force.csv has
10 significant digits, so rounding is 1e-10. Also at least 5 increments
(the run reached 1.5 mm).
"""
import csv
import sys

HOLDER_FORCE = 4900.0
TOLERANCE = 1e-6


def main(output):
    with open(output + "/punch_force.csv") as f:
        rows = [r for r in csv.DictReader(f) if float(r["punch_travel_mm"]) > 0]
    worst = max(abs(float(r["holder_force_N"]) - HOLDER_FORCE) / HOLDER_FORCE
                for r in rows)
    ok = worst <= TOLERANCE and len(rows) >= 5 \
        and abs(float(rows[-1]["punch_travel_mm"]) - 1.5) < 1e-9
    print("%s %d increments to %s mm, largest holder force error %.2e "
          "(allowed %.0e)" % ("ok  " if ok else "FAIL", len(rows),
                              rows[-1]["punch_travel_mm"], worst, TOLERANCE))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
