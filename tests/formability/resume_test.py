#!/usr/bin/env python3
"""The post-processor "forming limits" through a resume and on the console
(doc/user_guide.md §8.2):
- homogeneous_paths.prm run to its end prints the summary line "forming
  limit first crossed at t = 2 mm ..." (the FLC 0.16 - e2/2 is crossed at
  t = 1.85, the first increment above it is t = 2), also with --quiet;
- a copy of its output resumed with --resume from the checkpoint at the end
  of stage 2 repeats the uninterrupted run: every CSV table byte for byte
  but for the wall times (the strain paths and the first crossing come from
  the checkpoint: without them the path ratios of stage 3 and the summary
  would differ), and the same summary line;
- deepdraw --flc on the same prm writes flc.csv (the command line reaches
  app::run_flc_command).

    resume_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import pathlib
import shutil
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402
from script_test import run  # noqa: E402


def summary(log):
    lines = [line for line in log.splitlines()
             if line.startswith("deepdraw: forming limit")]
    return lines[-1] if lines else "(none)"


def main():
    args, source, work = script_test.start(__doc__)
    prm = str(source / "tests" / "formability" / "homogeneous_paths.prm")
    failures = []
    full = summary(run([args.deepdraw, prm, "--output-directory", "full"],
                       work, tail=600))
    expected = "deepdraw: forming limit first crossed at t = 2 mm at (X, Y) = ("
    print("summary:", full)
    if not full.startswith(expected):
        failures.append("the summary is '%s'" % full)
    quiet = summary(run([args.deepdraw, prm, "--output-directory", "quiet",
                         "--quiet"], work))
    if quiet != full:
        failures.append("with --quiet the summary is '%s'" % quiet)

    shutil.copytree(work / "full", work / "resumed")
    log = run([args.deepdraw, prm, "--output-directory", "resumed",
               "--resume"], work, tail=600)
    if "resumed at load 2" not in log:
        failures.append("the resumed run did not start at the end of stage 2")
    if summary(log) != full:
        failures.append("the resumed run's summary is '%s'" % summary(log))
    failures += script_test.same_tables(work / "full", work / "resumed")

    run([args.deepdraw, "--flc", prm, "--output-directory", "flc"], work)
    if not (work / "flc" / "flc.csv").exists():
        failures.append("deepdraw --flc wrote no flc.csv")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
