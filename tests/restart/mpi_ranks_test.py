#!/usr/bin/env python3
"""`mpirun -np 1 deepdraw FILE.prm` is the run without a launcher: every CSV
table equal cell for cell (but the wall times). More ranks: tests/parallel
(D199).

Expectations are exit codes and equal tables, so there is no tolerance.

    mpi_ranks_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import os
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402  (tests/script_test.py)

PRM = pathlib.Path(__file__).with_name("short_cup.prm")


def mpirun(ranks, deepdraw, output, work):
    """Runs deepdraw under mpirun with `ranks` ranks (oversubscribed, and
    allowed as root, as CI runs); returns (exit code, output)."""
    environment = dict(os.environ)
    environment["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
    environment["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    command = ["mpirun", "--oversubscribe", "-np", str(ranks), deepdraw,
               str(PRM), "--output-directory", output]
    print("running:", " ".join(command), flush=True)
    result = subprocess.run(command, cwd=work, env=environment,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=600)
    print(result.stdout[-3000:])
    return result.returncode, result.stdout


def main():
    args, _, work = script_test.start(__doc__)
    failures = []

    script_test.run([args.deepdraw, str(PRM), "--output-directory", "plain"],
                    work, tail=300)
    code, _ = mpirun(1, args.deepdraw, "one", work)
    if code != 0:
        failures.append(f"one rank under mpirun: exit code {code}")
    else:
        failures += script_test.same_tables(work / "plain", work / "one",
                                            "the run without mpirun")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
