#!/usr/bin/env python3
"""A run with `Linear solver/Reuse factorisation` stopped by SIGTERM and
resumed repeats the uninterrupted run exactly (D185): every increment's
first system is factorised and the forcing term starts afresh there, so a
resumed process, which has no kept factors, takes the same path. The case
is reused_factorization_test's (the short square cup with the option on).
Expectation: every CSV cell identical but the wall times and the orderings
counted (as restart/kill_and_resume_test, D55, D97); tolerance zero.

    reused_factorization_resume_test.py --deepdraw EXE --source-dir REPO
                                        --work-dir DIR
"""
import pathlib
import signal
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402
from script_test import run  # noqa: E402


def main():
    args, source, work = script_test.start(__doc__)
    (work / "reused.prm").write_text(
        "include %s\nsubsection Linear solver\n"
        "  set Reuse factorisation = true\nend\n"
        % (source / "tests" / "regression" / "square_cup_short.prm"))
    run([args.deepdraw, "reused.prm", "--output-directory", "full"], work,
        tail=300)
    failures = []
    process = subprocess.Popen([args.deepdraw, "reused.prm",
                                "--output-directory", "stopped"], cwd=work,
                               stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    statistics = work / "stopped" / "statistics.csv"
    deadline = time.time() + 120
    while (not statistics.exists()
           or len(statistics.read_text().splitlines()) < 11):
        if process.poll() is not None or time.time() > deadline:
            sys.exit("FAILED: the run ended before its tenth increment")
        time.sleep(0.002)
    process.send_signal(signal.SIGTERM)
    process.communicate(timeout=120)
    if process.returncode != 3:
        failures.append("SIGTERM gave exit code %d, not 3"
                        % process.returncode)
    log = run([args.deepdraw, "reused.prm", "--output-directory", "stopped",
               "--resume"], work, tail=300)
    if "resumed at load" not in log:
        failures.append("the run did not resume from its checkpoint")
    if "solves with a kept factorisation" not in log:
        failures.append("the resumed run did not report the reused solves")
    failures += script_test.same_tables(work / "full", work / "stopped")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
