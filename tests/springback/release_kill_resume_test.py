#!/usr/bin/env python3
"""Resuming inside a force release (D150): press_release.prm with its
release in 400 increments of 0.0025 and a checkpoint after every increment
is stopped with SIGTERM once the release has passed t = 1.2, and resumed
with --resume: the checkpoint holds the released loads, the support's node
and the displacement at the release's start, so the resumed run must
repeat the uninterrupted one bit for bit, every CSV table (but for the
wall-time columns and the orderings counted, as the other restart tests).

    release_kill_resume_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import csv
import pathlib
import signal
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402
from script_test import run  # noqa: E402


def last_load(path):
    try:
        with open(path) as f:
            rows = list(csv.reader(f))
        return float(rows[-1][1]) if len(rows) > 1 else 0.0
    except (OSError, ValueError, IndexError):
        return 0.0


def main():
    args, source, work = script_test.start(__doc__)
    text = script_test.write_case(source, work,
                                  "tests/springback/press_release.prm")
    text = text.replace("      set Initial increment = 0.25\n"
                        "      set Maximum increment = 0.25\n",
                        "      set Initial increment = 0.0025\n"
                        "      set Maximum increment = 0.0025\n")
    text += "subsection Checkpoint\n  set Interval = 1\nend\n"
    (work / "case" / "process.prm").write_text(text)
    run([args.deepdraw, "case/process.prm", "--output-directory", "full"],
        work, tail=300)
    stopped = subprocess.Popen([args.deepdraw, "case/process.prm",
                                "--output-directory", "stopped"], cwd=work,
                               stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
    while stopped.poll() is None and \
            last_load(work / "stopped" / "statistics.csv") <= 1.2:
        time.sleep(0.01)
    stopped.send_signal(signal.SIGTERM)
    output, _ = stopped.communicate()
    print(output[-300:])
    failures = []
    if stopped.returncode != 3:
        failures.append("the stopped run ended with exit code %d, not 3"
                        % stopped.returncode)
    log = run([args.deepdraw, "case/process.prm", "--output-directory",
               "stopped", "--resume"], work, tail=300)
    if "resumed at load 1." not in log:
        failures.append("the resumed run did not begin inside the release")
    failures += script_test.same_tables(work / "full", work / "stopped")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
