"""Physical checks of the square cup (DESIGN §5) on square_cup_short.prm.

- The force-controlled blank holder carries 4900 N at every converged
  increment. Its equation is one of the contact equations, whose residual
  the convergence test bounds by Newton/Force tolerance (1e-6 in the prm)
  times F_ref, the norm of all nodal internal forces (reactions included),
  a few times the holder force here: 1e-5 relative leaves a margin
  (measured < 1e-9). The prm's 1e-6 is tighter than the square cup's 1e-3 for
  this reason; the contact tests show 1e-8 on exactly converged increments.
- Plastic flow is isochoric and the elastic volume change is of order
  sigma/E (1e-3 at most here): the sheet volume stays within 0.5 % of
  L W T (the issue's tolerance).
- r0 = 0.71 and r90 = 0.70 are almost equal, so the draw-in at the two
  edge midpoints, DX and DY, agrees within 5 % once it is measurable
  (> 0.02 mm); the corner draws in as well (DD > 0).
- The punch force is positive (it pushes) and the punch travel column
  equals the load of statistics.csv row by row.
It also writes punch_force_landings.csv and draw_in_landings.csv: the rows
at the landing travels (multiples of Output interval = 0.5 mm), which every
Newton path reaches exactly, for the numdiff comparison with the reference.
"""
import csv
import sys

LENGTH, WIDTH, THICKNESS = 75.0, 75.0, 0.81
HOLDER_FORCE = 4900.0
LANDING_INTERVAL = 0.5  # Output/Output interval of the prm


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main(output):
    failures = []
    punch = rows(output + "/punch_force.csv")
    statistics = rows(output + "/statistics.csv")
    draw_in = rows(output + "/draw_in.csv")

    converged = [r for r in punch if float(r["punch_travel_mm"]) > 0]
    if len(converged) != len(statistics):
        failures.append("punch_force.csv has %d increments, statistics.csv %d"
                        % (len(converged), len(statistics)))
    worst_holder = max(abs(float(r["holder_force_N"]) / HOLDER_FORCE - 1)
                       for r in converged)
    if worst_holder > 1e-5:
        failures.append("holder force off by %.3g relative" % worst_holder)
    for r, s in zip(converged, statistics):
        if abs(float(r["punch_travel_mm"]) - float(s["load"])) > 1e-9:
            failures.append("travel %s != load %s" % (r["punch_travel_mm"], s["load"]))
            break
    if min(float(r["punch_force_N"]) for r in converged) <= 0:
        failures.append("punch force not positive")

    volume0 = LENGTH * WIDTH * THICKNESS
    worst_volume = max(abs(float(s["sheet_volume_mm3"]) / volume0 - 1)
                       for s in statistics)
    if worst_volume > 5e-3:
        failures.append("volume change %.3g > 0.5 %%" % worst_volume)

    last = draw_in[-1]
    dx, dy, dd = (float(last[k]) for k in ("DX_mm", "DY_mm", "DD_mm"))
    if dx < 0.02 or abs(dx - dy) > 0.05 * max(dx, dy) or dd <= 0:
        failures.append("draw-in DX %.4g DY %.4g DD %.4g" % (dx, dy, dd))

    for name in ("punch_force", "draw_in"):
        with open(output + "/" + name + ".csv") as f:
            lines = f.read().splitlines()
        landings = [line for line in lines[1:]
                    if float(line.split(",")[0]) > 0
                    and abs(float(line.split(",")[0]) / LANDING_INTERVAL
                            - round(float(line.split(",")[0]) / LANDING_INTERVAL)) < 1e-9]
        with open(output + "/" + name + "_landings.csv", "w") as f:
            f.write("\n".join([lines[0]] + landings) + "\n")
        if len(landings) != 6:
            failures.append("%s: %d rows at the landing travels, not 6"
                            % (name, len(landings)))

    print("holder force error %.3g, volume change %.3g, DX %.4f DY %.4f "
          "(%.2f %%) DD %.4f mm" % (worst_holder, worst_volume, dx, dy,
                                    100 * abs(dx - dy) / max(dx, dy), dd))
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
