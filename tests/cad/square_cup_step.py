#!/usr/bin/env python3
"""The short square cup (tests/regression/square_cup_short.prm: 12 x 12 x 2
elements, 0 -> 3 mm in 0.1 mm increments, residuals to 1e-6) run twice: with
the built-in square-cup tools, and with the same tools written as STEP files
by `deepdraw --write-square-cup-tools` and read back through the Contact
subsection of the shipped prm/square_cup_step.prm (Geometry = cad, doc/
tool_files.md). Punch force, holder force and lift, and the draw-in DX, DY,
DD must agree at every increment to 1e-6 of each column's largest magnitude
(measured: 1.5e-8 for the holder lift, at most 2.9e-9 in the other columns,
see doc/tool_files.md); the run on the STEP tools must report its three
tools as read (faces, patches).

    square_cup_step.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402
from script_test import run  # noqa: E402

TOLERANCE = 1e-6
TABLES = ("punch_force.csv", "draw_in.csv")


def main():
    args, source, work = script_test.start(__doc__)
    short = source / "tests" / "regression" / "square_cup_short.prm"

    # The tools of the short cup where prm/square_cup_step.prm expects them:
    # tools/square_cup in the prm's directory (here work/run).
    run([args.deepdraw, "--write-square-cup-tools", "run/tools/square_cup",
         str(short)], work)
    shipped = (source / "prm" / "square_cup_step.prm").read_text()
    start = shipped.index("subsection Contact")
    end = shipped.index("\nend\n", start) + len("\nend\n")
    (work / "run").mkdir(exist_ok=True)
    (work / "run" / "built_in.prm").write_text("include %s\n" % short)
    (work / "run" / "step.prm").write_text(
        "include %s\n%s" % (short, shipped[start:end]))

    run([args.deepdraw, "run/built_in.prm", "--output-directory", "built_in"],
        work)
    log = run([args.deepdraw, "run/step.prm", "--output-directory", "step"],
              work)

    failures = []
    for name in ("punch", "die", "blank holder"):
        if "tool '%s' from run/tools/square_cup/" % name not in log:
            failures.append("no report of the STEP tool '%s'" % name)
    failures += script_test.compare_tables(work / "built_in", work / "step",
                                           TABLES, TOLERANCE)[0]
    script_test.finish(failures)


if __name__ == "__main__":
    main()
