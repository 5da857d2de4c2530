"""Checks of the short square cup (square_cup_short.prm): physics, then the
regression against square_cup_short.expected/.

Physical checks (they do not follow from the equations being solved alone;
measured values of the stored run in brackets):
- Force balance of the quarter sheet: the forces of the three tools
  (tools.csv) and the reactions of the symmetry planes (reactions.csv:
  xmin_Fx, ymin_Fy; the other components there are internal forces of
  nodes free in that direction, not reactions) sum to zero in x, y and z.
  This ties the reported tool forces (friction included) to the nodal
  forces; the element's internal forces must be self-equilibrated. Each
  component to 1e-5 of the die force [1.0e-6: the residual of
  increments stopped at Force tolerance 1e-6].
- The force-controlled blank holder carries 4900 N. Its equation is one of
  the contact equations, bounded by Newton/Force tolerance: 2e-6 relative
  [< 1e-10 here; 6.9e-6 with the tolerance at 1e-5, so up to 7e-7 is
  legitimate at the prm's 1e-6].
- The holder rests on the thickest point of the flange, the blank edge on
  the x axis (the end of the OX profile): its lift holder_z equals
  T (exp(eps_edge) - 1) at both profile travels, to 1e-8 relative [2e-10,
  the 10 digits of the output; also with Force tolerance 1e-5 or 1e-8].
- The flange thickens (compressed around its circumference as it draws
  in): eps at the OX blank edge > 0 at 1.5 and 3 mm and growing [4.9e-5,
  4.5e-4]. The largest thinning on the diagonal OD at 3 mm lies at the
  punch corner, 30 mm < s0 < 46 mm (its nose runs from 37.4 to 45.4 mm on
  the diagonal; OD nodes every 8.8 mm) and is more than 3 times the
  thinning at the centre [s0 = 35.4 mm, 8.1 times].
- Plastic flow is isochoric and the elastic volume change is of order
  (1 - 2 nu) sigma / E: the sheet volume stays within 3e-4 of L W T
  [1.0e-4].
- The draw-in DX, DY, DD never decreases by more than 1e-5 mm from one
  increment to the next [the elastic stretching of the first 0.6 mm moves
  the edge out by up to 5.7e-6 mm, in steps of at most 3.5e-6 mm; from
  0.7 mm on it grows at every increment], and
  at 3 mm DX and DY agree within 2 % [0.58 %: r0 = 0.71 and r90 = 0.70
  differ by 1.4 %], DD > 0.
- The punch force is positive and grows at every increment up to 3 mm
  (far below its maximum) [smallest step 36 N]; the punch travel column
  equals the load of statistics.csv row by row.
- The time columns of statistics.csv time disjoint parts of an increment:
  assembly_s + contact_search_s + linear_solve_s + output_s <= wall_s in
  every row, to 1 ms (a margin for the separate clocks) [0.986 at most]; a
  part timed twice, or the elements inside the contact time, would break
  it. contact_search_s > 0 in every row: the contact coupling is timed
  whole (D212).

Regression: the rows of punch_force.csv and draw_in.csv at the landing
travels (multiples of Output interval = 0.5 mm, which every Newton path
reaches exactly; written to *_landings.csv in the output) and the thickness
profiles are compared with square_cup_short.expected/, every column with
its own tolerance TOLERANCE relative to the largest magnitude of that
column in the expected file (several columns cross zero). Noise measured
against the stored files, largest over the rows, relative to the column
scale:
  - MUMPS or KLU instead of UMFPACK: <= 1.3e-10 in every column (the
    10-digit output);
  - Force/Correction tolerance 1e-8 instead of 1e-6 (the convergence error
    of the stored values): <= 2.5e-6 (OD at 1.5 mm), <= 3e-7 elsewhere;
  - Force/Correction tolerance 1e-5: the values in NOISE below.
Each tolerance is about 5 times the larger of these, rounded up. Changing
the friction coefficient from 0.162 to 0.160 or the Swift coefficient by
0.1 % fails several columns.
To regenerate after an intended change: copy *_landings.csv and
thickness_*.csv from the test's output directory into
square_cup_short.expected/ and say why in the commit.
"""
import csv
import math
import pathlib
import sys

LENGTH, WIDTH, THICKNESS = 75.0, 75.0, 0.81
HOLDER_FORCE = 4900.0
LANDING_INTERVAL = 0.5  # Output/Output interval of the prm
EXPECTED = pathlib.Path(__file__).with_name("square_cup_short.expected")

# Largest deviation from the stored files with Force/Correction tolerance
# 1e-5 (see above), and the tolerance used, both relative to the column's
# largest magnitude.
NOISE = {
    ("punch_force_landings.csv", "punch_force_N"): 4.2e-8,
    ("punch_force_landings.csv", "holder_force_N"): 7.3e-7,
    ("punch_force_landings.csv", "holder_z_mm"): 1.8e-5,
    ("draw_in_landings.csv", "DX_mm"): 4.1e-7,
    ("draw_in_landings.csv", "DY_mm"): 8.0e-7,
    ("draw_in_landings.csv", "DD_mm"): 1.2e-6,
    ("thickness_OX_1.5mm.csv", "thickness_strain"): 2.5e-6,
    ("thickness_OX_3mm.csv", "thickness_strain"): 1.2e-6,
    ("thickness_OD_1.5mm.csv", "thickness_strain"): 4.0e-6,
    ("thickness_OD_3mm.csv", "thickness_strain"): 5.1e-7,
}
TOLERANCE = {
    ("punch_force_landings.csv", "punch_force_N"): 2e-7,
    ("punch_force_landings.csv", "holder_force_N"): 2e-6,
    ("punch_force_landings.csv", "holder_z_mm"): 1e-4,
    ("draw_in_landings.csv", "DX_mm"): 2e-6,
    ("draw_in_landings.csv", "DY_mm"): 4e-6,
    ("draw_in_landings.csv", "DD_mm"): 6e-6,
    ("thickness_OX_1.5mm.csv", "thickness_strain"): 1.3e-5,
    ("thickness_OX_3mm.csv", "thickness_strain"): 6e-6,
    ("thickness_OD_1.5mm.csv", "thickness_strain"): 2e-5,
    ("thickness_OD_3mm.csv", "thickness_strain"): 3e-6,
}
# The first column (travel, s0) is an input: equal to 1e-9 relative.
KEY_TOLERANCE = 1e-9


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def table(path):
    with open(path) as f:
        lines = [line for line in csv.reader(f) if line]
    return lines[0], [[float(x) for x in line] for line in lines[1:]]


def write_landings(output, failures):
    for name in ("punch_force", "draw_in"):
        with open(output + "/" + name + ".csv") as f:
            lines = f.read().splitlines()
        landings = []
        for line in lines[1:]:
            travel = float(line.split(",")[0])
            steps = travel / LANDING_INTERVAL
            if travel > 0 and abs(steps - round(steps)) < 1e-9:
                landings.append(line)
        with open(output + "/" + name + "_landings.csv", "w") as f:
            f.write("\n".join([lines[0]] + landings) + "\n")
        if len(landings) != 6:
            failures.append("%s: %d rows at the landing travels, not 6"
                            % (name, len(landings)))


def compare_with_expected(output, failures):
    for name in sorted({file for file, _ in TOLERANCE}):
        header, expected = table(EXPECTED / name)
        header_out, actual = table(pathlib.Path(output) / name)
        if header_out != header or len(actual) != len(expected):
            failures.append("%s: columns %s, %d rows; expected %s, %d rows"
                            % (name, header_out, len(actual), header,
                               len(expected)))
            continue
        for a, e in zip(actual, expected):
            if abs(a[0] - e[0]) > KEY_TOLERANCE * max(abs(e[0]), 1.0):
                failures.append("%s: first column %g, expected %g"
                                % (name, a[0], e[0]))
                break
        for j, column in enumerate(header[1:], 1):
            scale = max(abs(e[j]) for e in expected)
            deviation = max(abs(a[j] - e[j]) for a, e in zip(actual, expected))
            relative = deviation / scale
            tolerance = TOLERANCE[(name, column)]
            ok = relative <= tolerance
            print("%s %-24s %-16s deviation %.2e of %.4g (tolerance %.1e, "
                  "noise %.1e)" % ("ok  " if ok else "FAIL", name, column,
                                   relative, scale, tolerance,
                                   NOISE[(name, column)]))
            if not ok:
                failures.append("%s %s deviates by %.3g of its scale > %.3g"
                                % (name, column, relative, tolerance))


def physical_checks(output, failures):
    punch = rows(output + "/punch_force.csv")
    statistics = rows(output + "/statistics.csv")
    draw_in = rows(output + "/draw_in.csv")
    tools = rows(output + "/tools.csv")
    reactions = rows(output + "/reactions.csv")

    converged = [r for r in punch if float(r["punch_travel_mm"]) > 0]
    if len(converged) != len(statistics):
        failures.append("punch_force.csv has %d increments, statistics.csv %d"
                        % (len(converged), len(statistics)))
    for r, s in zip(converged, statistics):
        if abs(float(r["punch_travel_mm"]) - float(s["load"])) > 1e-9:
            failures.append("travel %s != load %s"
                            % (r["punch_travel_mm"], s["load"]))
            break

    # Force balance of the sheet.
    names = ("punch", "die", "blank holder")
    worst_balance = 0.0
    for t, r in zip(tools, reactions):
        if float(t["load"]) == 0:
            continue
        die = abs(float(t["die_Fz"]))
        balance = (sum(float(t[n + "_Fx"]) for n in names) + float(r["xmin_Fx"]),
                   sum(float(t[n + "_Fy"]) for n in names) + float(r["ymin_Fy"]),
                   sum(float(t[n + "_Fz"]) for n in names))
        worst_balance = max([worst_balance] + [abs(b) / die for b in balance])
    if worst_balance > 1e-5:
        failures.append("force balance off by %.3g of the die force"
                        % worst_balance)

    worst_holder = max(abs(float(r["holder_force_N"]) / HOLDER_FORCE - 1)
                       for r in converged)
    if worst_holder > 2e-6:
        failures.append("holder force off by %.3g relative" % worst_holder)

    # Holder lift = thickening of the flange at the OX blank edge; the
    # flange thickens, the punch corner thins.
    edge = {}
    worst_lift = 0.0
    for travel in ("1.5", "3"):
        profile = rows(output + "/thickness_OX_%smm.csv" % travel)
        edge[travel] = float(profile[-1]["thickness_strain"])
        lift = THICKNESS * (math.exp(edge[travel]) - 1)
        holder_z = [float(r["holder_z_mm"]) for r in punch
                    if abs(float(r["punch_travel_mm"]) - float(travel)) < 1e-9]
        if len(holder_z) != 1 or lift <= 0:
            failures.append("no holder position or no lift at %s mm" % travel)
            continue
        worst_lift = max(worst_lift, abs(holder_z[0] / lift - 1))
    if worst_lift > 1e-8:
        failures.append("holder lift != flange thickening at the edge: %.3g"
                        % worst_lift)
    if not (0 < edge["1.5"] < edge["3"]):
        failures.append("flange edge thickness strain %.3g, %.3g: no growing "
                        "thickening" % (edge["1.5"], edge["3"]))
    diagonal = [(float(r["s0_mm"]), float(r["thickness_strain"]))
                for r in rows(output + "/thickness_OD_3mm.csv")]
    s_min, eps_min = min(diagonal, key=lambda p: p[1])
    eps_centre = diagonal[0][1]
    if not (30 < s_min < 46 and eps_min < 3 * eps_centre < 0):
        failures.append("largest thinning on OD %.3g at s0 = %.1f mm (centre "
                        "%.3g)" % (eps_min, s_min, eps_centre))

    volume0 = LENGTH * WIDTH * THICKNESS
    worst_volume = max(abs(float(s["sheet_volume_mm3"]) / volume0 - 1)
                       for s in statistics)
    if worst_volume > 3e-4:
        failures.append("volume change %.3g > 3e-4" % worst_volume)

    worst_retreat = 0.0
    for previous, current in zip(draw_in, draw_in[1:]):
        for k in ("DX_mm", "DY_mm", "DD_mm"):
            worst_retreat = max(worst_retreat,
                                float(previous[k]) - float(current[k]))
    if worst_retreat > 1e-5:
        failures.append("draw-in decreases by %.3g mm" % worst_retreat)
    last = draw_in[-1]
    dx, dy, dd = (float(last[k]) for k in ("DX_mm", "DY_mm", "DD_mm"))
    if dx < 0.02 or abs(dx - dy) > 0.02 * max(dx, dy) or dd <= 0:
        failures.append("draw-in DX %.4g DY %.4g DD %.4g" % (dx, dy, dd))

    worst_share = 0.0
    for s in statistics:
        parts = sum(float(s[k]) for k in ("assembly_s", "contact_search_s",
                                          "linear_solve_s", "output_s"))
        wall = float(s["wall_s"])
        worst_share = max(worst_share, parts / wall)
        if parts > wall + 1e-3 or float(s["contact_search_s"]) <= 0:
            failures.append("increment %s: timed parts %.4g s of a wall time "
                            "of %.4g s, contact %s s"
                            % (s["increment"], parts, wall,
                               s["contact_search_s"]))
            break

    forces = [float(r["punch_force_N"]) for r in converged]
    smallest_step = min(b - a for a, b in zip(forces, forces[1:]))
    if forces[0] <= 0 or smallest_step <= 0:
        failures.append("punch force not positive and growing (first %.4g, "
                        "smallest step %.3g N)" % (forces[0], smallest_step))

    print("force balance %.2g, holder force error %.2g, holder lift vs edge "
          "thickening %.2g, edge strain %.3g / %.3g, OD thinning %.3g at %.1f "
          "mm (centre %.3g), volume change %.3g, draw-in retreat %.2g mm, DX "
          "%.4f DY %.4f (%.2f %%) DD %.4f mm, smallest punch force step "
          "%.3g N, timed parts at most %.3f of the wall time"
          % (worst_balance, worst_holder, worst_lift, edge["1.5"],
                      edge["3"], eps_min, s_min, eps_centre, worst_volume,
                      worst_retreat, dx, dy, 100 * abs(dx - dy) / max(dx, dy),
                      dd, smallest_step, worst_share))


def main(output):
    failures = []
    physical_checks(output, failures)
    write_landings(output, failures)
    compare_with_expected(output, failures)
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
