#!/usr/bin/env python3
"""A run with `Linear solver/Reuse factorisation` stopped by SIGTERM and
resumed repeats the uninterrupted run exactly (D185): every increment's
first system is factorised and the forcing term starts afresh there, so a
resumed process, which has no kept factors, takes the same path. The case
is reused_factorization_test's (the short square cup with the option on).
The same with `Factorisation precision = single` (D226): the resumed
process starts in single precision, where the uninterrupted one switched
from double after the stage's first increment, and must take the same path.
Expectation: every CSV cell identical but the wall times and the orderings
counted (as restart/kill_and_resume_test, D55, D97); tolerance zero.

    reused_factorization_resume_test.py --deepdraw EXE --source-dir REPO
                                        --work-dir DIR
"""
import pathlib
import signal
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402
from script_test import run  # noqa: E402


CASES = (("reused", ("Reuse factorisation", "true"),
          "solves with a kept factorisation"),
         ("single", ("Factorisation precision", "single"),
          "factorisations in single precision"))


def stop_and_resume(args, work, name, summary):
    """Runs name.prm whole and stopped by SIGTERM after 10 increments and
    resumed; returns the failures."""
    prm = name + ".prm"
    whole, stopped = name + "_full", name + "_stopped"
    run([args.deepdraw, prm, "--output-directory", whole], work, tail=300)
    failures = []
    process = subprocess.Popen([args.deepdraw, prm,
                                "--output-directory", stopped], cwd=work,
                               stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    script_test.stop_after(process, work / stopped, 10, signal.SIGTERM)
    if process.returncode != 3:
        failures.append("%s: SIGTERM gave exit code %d, not 3"
                        % (name, process.returncode))
    log = run([args.deepdraw, prm, "--output-directory", stopped,
               "--resume"], work, tail=300)
    if "resumed at load" not in log:
        failures.append("%s: the run did not resume from its checkpoint"
                        % name)
    if summary not in log:
        failures.append("%s: the resumed run did not report '%s'"
                        % (name, summary))
    return failures + script_test.same_tables(work / whole, work / stopped)


def main():
    args, source, work = script_test.start(__doc__)
    failures = []
    for name, setting, summary in CASES:
        script_test.write_linear_solver_case(
            work, name + ".prm",
            source / "tests" / "regression" / "square_cup_short.prm",
            [setting])
        failures += stop_and_resume(args, work, name, summary)
    script_test.finish(failures)


if __name__ == "__main__":
    main()
