#!/usr/bin/env python3
"""Resuming between the stages of a process (D101): the three-stage run of
tests/stages/press_lift_press.prm writes a checkpoint at the end of each
stage but the last. A copy of its output directory, resumed with --resume,
begins stage 3 from the checkpoint of the end of stage 2 and must repeat the
uninterrupted run: every CSV table byte for byte, but for the wall-time
columns (*_s) and the orderings counted in statistics.csv (D97, as the
other restart tests).
On the same checkpoint, a prm whose stage 3 moves the holder twice as far
is accepted (a stage after the checkpoint's may change) and gives twice the
force gain; a prm whose stage 1 differs is refused with exit code 2 naming
the parameter, and the output directory is left byte for byte as it was.

    stage_resume_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import csv
import pathlib
import shutil
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402
from script_test import run, snapshot  # noqa: E402

def main():
    args, source, work = script_test.start(__doc__)
    prm = source / "tests" / "stages" / "press_lift_press.prm"
    (work / "case").mkdir()
    text = prm.read_text().replace("../contact/data",
                                   str(source / "tests" / "contact" / "data"))
    (work / "case" / "process.prm").write_text(text)
    run([args.deepdraw, "case/process.prm", "--output-directory", "full"],
        work)
    shutil.copytree(work / "full", work / "resumed")
    log = run([args.deepdraw, "case/process.prm", "--output-directory",
               "resumed", "--resume"], work)
    failures = []
    if "resumed at load 2" not in log:
        failures.append("the resumed run did not start at the end of stage 2")
    failures += script_test.compare_runs(work / "full", work / "resumed",
                                         "the uninterrupted run")

    # A later stage may change: twice the holder's travel in stage 3.
    shutil.copytree(work / "full", work / "changed")
    (work / "case" / "changed.prm").write_text(
        text.replace("-2e-4*(t-2)", "-4e-4*(t-2)"))
    run([args.deepdraw, "case/changed.prm", "--output-directory", "changed",
         "--resume"], work)
    forces = {}
    for name in ("full", "changed"):
        with open(work / name / "tools.csv") as f:
            rows = {float(r["load"]): -float(r["holder_Fz"])
                    for r in csv.DictReader(f)}
        forces[name] = rows[3.0] - rows[2.25]
    ratio = forces["changed"] / forces["full"]
    print("force gain from t = 2.25 to 3: %.6g N, with stage 3 changed %.6g "
          "N (ratio %.6f)" % (forces["full"], forces["changed"], ratio))
    # Linear elasticity: 2 within the plate's strain, 1e-3.
    if abs(ratio - 2.0) > 2e-3:
        failures.append("the changed stage 3 gives %.6f times the force gain"
                        % ratio)

    # An earlier stage may not change: refused, nothing touched.
    shutil.copytree(work / "full", work / "refused")
    before = snapshot(work / "refused")
    (work / "case" / "refused.prm").write_text(
        text.replace("set Blank holder force = 30",
                     "set Blank holder force = 31"))
    result = subprocess.run([args.deepdraw, "case/refused.prm",
                             "--output-directory", "refused", "--resume"],
                            cwd=work, capture_output=True, text=True)
    print(result.stderr.strip())
    if result.returncode != 2 or "Process/Blank holder force: 30 -> 31" \
            not in result.stderr:
        failures.append("a changed stage 1 gave exit code %d: %s"
                        % (result.returncode, result.stderr.strip()))
    if snapshot(work / "refused") != before:
        failures.append("the refused resume changed the output directory")

    script_test.finish(failures)


if __name__ == "__main__":
    main()
