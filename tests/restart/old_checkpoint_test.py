#!/usr/bin/env python3
"""A checkpoint written before stages and post-processors (format 1,
data/checkpoint_format_1/output: the plate of data/checkpoint_format_1/
case.prm pressed by a force-controlled holder, to load 0.6, by the
deepdraw of commit 6d4f1ac) resumes with this deepdraw (D101): the new
parameters are at their defaults, the VTU counter and PVD steps of the old
format are the "visualization" post-processor's data. Resumed to load 1 it
must repeat the run of this deepdraw from the start: every CSV table but
for the wall times (*_s) and the orderings counted in statistics.csv (D97),
to 1e-12 relative or to 1e-12 of the table's largest number (D190: the
checkpoint and its tables were written on another machine, whose CPU
rounds the solver's sums differently; they differ by round-off, the
residuals of 1e-17 and the reactions of 1e-16 N of a 30 N plate; byte for
byte on one machine is what the restart tests of this deepdraw check).
A format-1 checkpoint of another model (another holder force) is refused
with exit code 2 naming the parameter, and the folder is left as it was.

    old_checkpoint_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import pathlib
import shutil
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402
from script_test import run, snapshot  # noqa: E402

def main():
    args, source, work = script_test.start(__doc__)
    data = source / "tests" / "restart" / "data" / "checkpoint_format_1"
    prm = str(data / "case.prm")
    run([args.deepdraw, prm, "--output-directory", "fresh"], work)
    shutil.copytree(data / "output", work / "resumed")
    log = run([args.deepdraw, prm, "--output-directory", "resumed",
               "--resume"], work)
    failures = []
    if "resumed at load 0.6" not in log:
        failures.append("the run did not resume at load 0.6")
    failures += script_test.close_tables(work / "fresh", work / "resumed",
                                         "the run from the start")

    shutil.copytree(data / "output", work / "refused")
    before = snapshot(work / "refused")
    other = work / "other.prm"
    other.write_text(
        (data / "case.prm").read_text()
        .replace("set Blank holder force = 30", "set Blank holder force = 40")
        .replace("../../../contact/data/",
                 str(source / "tests" / "contact" / "data") + "/"))
    result = subprocess.run([args.deepdraw, str(other), "--output-directory",
                             "refused", "--resume"], cwd=work,
                            capture_output=True, text=True)
    print(result.stderr.strip())
    if result.returncode != 2 \
            or "Process/Blank holder force: 30 -> 40" not in result.stderr:
        failures.append("another model's format-1 checkpoint gave exit "
                        "code %d" % result.returncode)
    if snapshot(work / "refused") != before:
        failures.append("the refused resume changed the output directory")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
