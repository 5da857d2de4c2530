#!/usr/bin/env python3
"""Checkpoint and restart of an adaptive run (D84, doc/user_guide.md §4.3):
the short square cup of restart/kill_and_resume_test (8 x 8 x 2 cells, 15
increments, a checkpoint after each), refined in the plane by the plastic
strain jump after increments 8 and 12 (128 -> 224 -> 566 cells, within
the limit of 600 cells with deal.II's closure of the flags), is killed
with SIGKILL after increment 9 (one refinement behind it) and after
increment 13 (two), and resumed each time. The resumed run replays the
refinements of the checkpoint on the blank's mesh and must repeat the
uninterrupted run: every CSV value (adaptivity.csv included) and every VTU
byte identical, apart from wall times (the *_s columns of statistics.csv
and adaptivity.csv), the orderings counted in statistics.csv (D97) and
deal.II's date line, as for fixed meshes (D55);
the tolerance is zero."""
import pathlib
import signal
import sys

from adaptivity_test_tools import prepare, read

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]
                       / "restart"))
import kill_and_resume_test as restart  # noqa: E402
import script_test  # noqa: E402  (tests/script_test.py, via restart)

ADAPTIVE = """include {base}
subsection Adaptivity
  set Enabled                 = true
  set Refinement interval     = 4
  set Maximum level           = 2
  set Maximum number of cells = 600
  set Indicator               = plastic strain jump
  set Jump threshold          = 1e-5
  set Refinement              = in_plane
end
"""


def main():
    args, work = prepare()
    prm = work / "adaptive_cup.prm"
    prm.write_text(ADAPTIVE.format(base=restart.PRM))
    restart.PRM = prm
    failures = []

    reference = work / "uninterrupted"
    restart.run_to_end(args.deepdraw, work, reference)
    cycles = len(read(reference / "adaptivity.csv"))
    print(f"uninterrupted run: {cycles} refinements")
    if cycles != 2:
        failures.append(f"{cycles} refinements, expected 2 (after 8 and 12)")
    for row in read(reference / "adaptivity.csv"):
        if int(row["cells_after"]) > 600:
            failures.append(f"{row['cells_after']} cells, more than the "
                            "Maximum number of cells, 600")

    killed = work / "killed"
    process = restart.start(args.deepdraw, work, killed)
    script_test.stop_after(process, killed, 9, signal.SIGKILL)
    process = restart.start(args.deepdraw, work, killed, "--resume")
    script_test.stop_after(process, killed, 13, signal.SIGKILL)
    out = restart.run_to_end(args.deepdraw, work, killed, "--resume")
    if "resumed at load" not in out:
        failures.append("the resumed run does not say where it resumed")
    failures += restart.compare(reference, killed,
                                "SIGKILL at 9 and 13, resumed")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
