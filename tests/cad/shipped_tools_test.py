#!/usr/bin/env python3
"""The STEP tools shipped with prm/square_cup_step.prm,
prm/cylindrical_cup.prm and prm/esaform2021_cup.prm (prm/tools/square_cup,
prm/tools/cylindrical_cup, prm/tools/esaform2021_cup) are what `deepdraw --write-square-cup-tools DIR PRM` writes today from the
prm's Tools subsection: the same files line for line, but for the date in
the STEP header (FILE_NAME). So a change of the builder or of the prm's
tool dimensions cannot leave the shipped files behind; and both prms run as
a newcomer types them (doc/user_guide.md §7): every shipped prm passes
`deepdraw --check prm/NAME.prm` started in the repository's root.

    shipped_tools_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402
from script_test import run  # noqa: E402

SETS = (("square_cup", "square_cup.prm"),
        ("cylindrical_cup", "cylindrical_cup.prm"),
        ("esaform2021_cup", "esaform2021_cup.prm"))
TOOLS = ("punch.step", "die.step", "blank_holder.step")


def without_date(text):
    # FILE_NAME('name','2026-12-03T07:23:53',...: the second field.
    return re.sub(r"(FILE_NAME\('[^']*',)'[^']*'", r"\1''", text)


def main():
    args, source, work = script_test.start(__doc__)
    failures = []
    for folder, prm in SETS:
        written = work / folder
        run([args.deepdraw, "--write-square-cup-tools", str(written),
             str(source / "prm" / prm)], work)
        for tool in TOOLS:
            shipped = source / "prm" / "tools" / folder / tool
            if not shipped.is_file():
                failures.append("%s is not shipped" % shipped)
                continue
            if without_date(shipped.read_text()) != \
                    without_date((written / tool).read_text()):
                failures.append("%s differs from what --write-square-cup-"
                                "tools writes for prm/%s" % (shipped, prm))
            else:
                print("%s/%s: as written today" % (folder, tool))
    for prm in sorted((source / "prm").glob("*.prm")):
        # run() stops the test on a non-zero exit code, naming it.
        result = run([args.deepdraw, "--check", "prm/" + prm.name], source)
        if "the input is valid" not in result:
            failures.append("deepdraw --check prm/%s fails" % prm.name)
    script_test.finish(failures)


if __name__ == "__main__":
    main()
