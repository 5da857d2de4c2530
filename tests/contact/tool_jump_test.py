#!/usr/bin/env python3
"""A punch that jumps 3 mm at t = 0.5 (more than the 2 mm search distance)
would pass through the sheet within one increment. The increment must be
cut back, and since no cut-back can make a jump shorter, the run must stop
with exit code 3 naming the tool, keep the tables of the converged
increments whole (every row complete, the last one before the jump) and
leave a checkpoint (D56)."""
import csv
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402  (tests/script_test.py)


def main():
    args, _, work = script_test.start(__doc__)
    prm = work / "jump.prm"
    prm.write_text("""include prm/square_cup.prm
subsection Geometry
  set Elements along x = 8
  set Elements along y = 8
end
subsection Process
  set Final load = 1
end
subsection Contact
  subsection Tool 1
    set Translation = 0; 0; -(t < 0.5 ? t : t + 3)
  end
end
""")
    output = work / "output"
    run = subprocess.run([args.deepdraw, str(prm), "--output-directory",
                          str(output), "--quiet"], cwd=work,
                         capture_output=True, text=True)
    print(run.stdout, run.stderr)
    failures = []
    if run.returncode != 3:
        failures.append(f"exit code {run.returncode}, not 3")
    if "tool 'punch' moves" not in run.stderr:
        failures.append("the message does not name the punch")
    with open(output / "punch_force.csv") as f:
        rows = list(csv.reader(f))
    if any(len(row) != len(rows[0]) for row in rows):
        failures.append("punch_force.csv has an incomplete row")
    last_travel = float(rows[-1][0])
    print(f"last converged travel {last_travel}")
    if not 0.4 < last_travel < 0.5:
        failures.append(f"last row at {last_travel}, expected just below 0.5")
    if not (output / "checkpoint.bin").exists():
        failures.append("no checkpoint")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
