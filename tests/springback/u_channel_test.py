#!/usr/bin/env python3
"""A coarse NUMISHEET'93 draw bending (prm/u_channel.prm, D154-D156):
88 elements along the strip (2 mm), drawn 25 mm and released by force.
Expectations independent of the code:

- before the release the section is the tools' channel: the wall stands
  between the punch's side (x = 35) and the die's wall (x = 36), so that
  the mid-surface has 1 - 0.78 = 0.22 mm of free play across it; over the
  straight part of the wall of this draw (s0 = 40 to 50, 10 mm along the
  wall) it can tilt by at most atan(0.22 / 10) = 1.26 degrees, and theta1
  and theta2 are 90 degrees within that (measured 89.63 and 89.89; theta1
  holds also the bottom's bow, its centre 0.09 mm above its end at s0 = 20,
  0.3 degrees);
- the force release turns the flange down against the wall (the bending
  moment of the die shoulder relaxes; at 70 mm theta2 falls from 90.1 to
  77.8 degrees, doc/results.md): theta2 falls by more than 1 degree
  (measured 2.57; the bound is a sign with a margin of half the measured
  value, not a value);
- the release leaves no tool acting (their forces zero at its end) and its
  increments converge (at most 18 Newton iterations each: measured 9 in
  the first, 5 to 7 in the nine others; the bound is twice the largest).

- the same draw released by tool retraction with the law and the settings
  of prm/u_channel_retraction.prm, resumed from the checkpoint at the end
  of the draw (D208: the holder up, the die out and down at once, the
  punch up out of the channel; a viscous stabilization 0.002 falling to 0
  before the stage's end, the stage's Newton tolerance 1e-5, one
  iteration at least) frees the part of every tool (the run ends with exit
  0 only then) and leaves the shape of the force release: both methods
  release the same loaded part, and since c is 0 at the end, the last
  state is a static one. Measured: 0.005 deg, 0.07 deg, 0.3 % (Intel
  Xeon, 253 increments, about 20 s alone); 0.003 deg, 0.10 deg, 0.003 %
  (AMD EPYC, 161 retraction increments after the draw's 113, 24 s);
  asserted 0.3 deg and 1 %.
  Not asserted: the tools in turn without these settings (D198's law).
  That path is not robust: on an AMD EPYC it stops in the holder's lift,
  its flange pairs switching stick and slip in a cycle (D222).
The draw has the prm's Contact/Augmentation scaling 0.005 (D198) and the
prm's Newton settings (up to 100 iterations, no separate bound on the
holder's force, D205). Measured on 2 cores: 51 s for the draw and the
force release (107 + 10 increments with the tolerances 1e-4, beside
another run).

    u_channel_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import csv
import math
import pathlib
import re
import shutil
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402

ELEMENTS = 88          # 2 mm elements along the strip
STROKE = 25            # mm of punch travel
# The channel's parts by initial distance s0 from the axis, chosen on the
# section of this draw as for prm/u_channel.prm (D156): the bottom lies
# flat to s0 = 27, the wall is straight from s0 = 39 (the end of the punch
# radius) to 51 (the beginning of the die shoulder), the flange begins at
# s0 = 61 (beyond the shoulder, x > 41).
PARTS = "bottom: 0, 20; wall: 40, 50; flange: 65, 165"
# The wall's tilt the clearance allows (module docstring): free play
# 1 - 0.78 mm over the 10 mm of s0 = 40 to 50.
BEFORE_TOLERANCE = math.degrees(math.atan(0.22 / 10.))
THETA2_FALL = 1.0          # deg; measured 2.57
RELEASE_ITERATIONS = 18    # per increment; measured at most 9 (twice that)
ANGLE_AGREEMENT = 0.3      # deg, retraction against force; measured 0.10
RHO_AGREEMENT = 0.01       # relative; measured 0.003 at most
# The law of prm/u_channel_retraction.prm (D208) at this stroke: the punch
# 40 mm up, out of the 25 mm channel.
STABILIZED = """subsection Process
  set Final load = %(end)g
  subsection Stage 2
    set Release method = tool retraction
    set Viscous stabilization = 0.002*min(1, %(end)g-t)
    subsection Newton
      set Minimum iterations   = 1
      set Force tolerance      = 1e-5
      set Correction tolerance = 1e-5
    end
    subsection Tool 1
      set Translation = 0; 0; 4*max(0, min(t-%(s)g-3, 10))
    end
    subsection Tool 2
      set Translation = 10*max(0, min(t-%(s)g-1, 2)); 0; -30*max(0, min(t-%(s)g-1, 2))
    end
    subsection Tool 3
      set Control     = displacement
      set Translation = 0; 0; 3*max(0, min(t-%(s)g, 1))
    end
    subsection Load stepping
      set Initial increment = 0.1
      set Maximum increment = 0.5
      set Minimum increment = 1e-6
      set Maximum cut-backs = 40
    end
  end
end
""" % {"s": STROKE, "end": STROKE + 10}


def variant(text, tools):
    """The coarse case of prm/u_channel.prm: its tools named absolutely,
    ELEMENTS elements, STROKE mm, the support at the channel's bottom,
    PARTS, no VTU. The element's enhanced parameters may take 100
    evaluations: with the default 25 this mesh stops at 5.4 mm (D156)."""
    text = text.replace("tools/u_channel/", str(tools) + "/")
    text = re.sub(r"set Elements along x( *)= \d+",
                  r"set Elements along x\g<1>= %d" % ELEMENTS, text)
    text = text.replace("set Element = incompatible modes",
                        "set Enhanced iterations = 100\n"
                        "  set Element = incompatible modes")
    # Tolerances 1e-4, not the prm's 1e-3: on some machines (their CPU
    # rounds the solver's sums differently) the 1e-3 path converges at
    # 5.38 mm to a state (force residual 9.6e-4) from which every further
    # increment fails down to the minimum; 1e-4 draws through (D190).
    text = re.sub(r"set (Force|Correction) tolerance( *)= 1e-3",
                  r"set \1 tolerance\2= 1e-4", text)
    text = text.replace("set Final load = 70", "set Final load = %g" % STROKE)
    text = text.replace("set Final load         = 71",
                        "set Final load         = %g" % (STROKE + 1))
    text = text.replace("point(0, 0, -70)", "point(0, 0, %g)" % -STROKE)
    text = re.sub(r"set Channel parts    = .*",
                  "set Channel parts    = " + PARTS, text)
    return text.replace("subsection Output\n",
                        "subsection Output\n  set Write VTU = false\n")


def main():
    args, source, work = script_test.start(__doc__)
    text = (source / "prm" / "u_channel.prm").read_text()
    tools = source / "prm" / "tools" / "u_channel"
    (work / "case").mkdir()
    (work / "case" / "force.prm").write_text(variant(text, tools))
    script_test.run([args.deepdraw, "case/force.prm", "--output-directory",
                     "force"], work, tail=2000)
    output = work / "force"
    rows = {int(row["stage"]): row
            for row in script_test.csv_rows(output / "section_measures.csv")}
    checks = script_test.Checks()
    failures = checks.failures
    before, after = rows[1], rows[2]
    checks.check("before release: theta1 (deg)", before["theta1_deg"], 90.,
                 BEFORE_TOLERANCE, False)
    checks.check("before release: theta2 (deg)", before["theta2_deg"], 90.,
                 BEFORE_TOLERANCE, False)
    fall = before["theta2_deg"] - after["theta2_deg"]
    print("force release: theta1 %.4f -> %.4f, theta2 %.4f -> %.4f (falls "
          "%.4f, at least %g), rho %.2f -> %.2f mm"
          % (before["theta1_deg"], after["theta1_deg"], before["theta2_deg"],
             after["theta2_deg"], fall, THETA2_FALL, before["rho_mm"],
             after["rho_mm"]))
    if not fall > THETA2_FALL:
        failures.append("the force release turned theta2 by %.4g deg" % -fall)
    last = script_test.csv_rows(output / "tools.csv")[-1]
    for column, value in last.items():
        if column.endswith(("_Fx", "_Fy", "_Fz")):
            checks.check("released: " + column, value, 0., 1e-9, False)
    with open(output / "statistics.csv") as f:
        release = [row for row in csv.DictReader(f)
                   if float(row["load"]) > STROKE]
    iterations = [int(row["newton_iterations"]) for row in release]
    print("release increments: %d, Newton iterations %s"
          % (len(release), iterations))
    if len(release) != 10 or max(iterations) > RELEASE_ITERATIONS:
        failures.append("release: %d increments, iterations %s"
                        % (len(release), iterations))
    check_retraction(args, work, after, checks, "stabilized", STABILIZED)
    script_test.finish(failures)


def check_retraction(args, work, force, checks, name, settings):
    """The draw's checkpoint released by tool retraction with settings
    (module docstring): the run must end (exit 0: every pair open) with the
    force release's shape."""
    (work / "case" / (name + ".prm")).write_text(
        "include case/force.prm\n" + settings)
    shutil.copytree(work / "force", work / name)
    script_test.run([args.deepdraw, "case/%s.prm" % name, "--output-directory",
                     name, "--resume"], work, tail=2000)
    after = {int(row["stage"]): row for row in script_test.csv_rows(
        work / name / "section_measures.csv")}[2]
    print("tool retraction (%s): theta1 %.4f, theta2 %.4f, rho %.2f mm "
          "(force release %.4f, %.4f, %.2f)"
          % (name, after["theta1_deg"], after["theta2_deg"], after["rho_mm"],
             force["theta1_deg"], force["theta2_deg"], force["rho_mm"]))
    for angle in ("theta1_deg", "theta2_deg"):
        checks.check(name + " against force: " + angle, after[angle],
                     force[angle], ANGLE_AGREEMENT, False)
    checks.check(name + " against force: rho_mm", after["rho_mm"],
                 force["rho_mm"], RHO_AGREEMENT, True)
    for column, value in script_test.csv_rows(
            work / name / "tools.csv")[-1].items():
        if column.endswith(("_Fx", "_Fy", "_Fz")):
            checks.check(name + ": " + column, value, 0., 1e-9, False)


if __name__ == "__main__":
    main()
