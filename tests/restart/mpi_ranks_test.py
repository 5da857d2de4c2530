#!/usr/bin/env python3
"""`mpirun -np 1 deepdraw FILE.prm` is the run without a launcher: every CSV
table equal cell for cell (but the wall times). More ranks: tests/parallel
(D199).

Expectations are exit codes and equal tables, so there is no tolerance.

    mpi_ranks_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]
                       / "parallel"))
import script_test  # noqa: E402  (tests/script_test.py)
import mpirun_tools  # noqa: E402  (tests/parallel/mpirun_tools.py)

PRM = pathlib.Path(__file__).with_name("short_cup.prm")


def main():
    args, _, work = script_test.start(__doc__)
    failures = []

    script_test.run([args.deepdraw, str(PRM), "--output-directory", "plain"],
                    work, tail=300)
    code, _ = mpirun_tools.run(1, args.deepdraw, work, PRM,
                               "--output-directory", "one")
    if code != 0:
        failures.append(f"one rank under mpirun: exit code {code}")
    else:
        failures += script_test.same_tables(work / "plain", work / "one",
                                            "the run without mpirun")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
