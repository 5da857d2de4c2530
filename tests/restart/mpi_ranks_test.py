#!/usr/bin/env python3
"""deepdraw runs on one MPI rank until parallel runs are built (issue 29,
doc/decisions.md D195): `mpirun -np 2 deepdraw FILE.prm` ends with exit
code 2 and one line, printed once, naming the rank count, and writes
nothing (without the check both ranks ran the whole simulation into one
output folder, and the second stopped on the first's lock); `mpirun -np 1`
is the run without a launcher, every CSV table equal cell for cell (but the
wall times).

Expectations are exit codes, the file system and equal tables, so there is
no tolerance.

    mpi_ranks_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import os
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402  (tests/script_test.py)

PRM = pathlib.Path(__file__).with_name("short_cup.prm")
MESSAGE = ("deepdraw: error in the input: started on 2 MPI ranks; deepdraw "
           "runs on one rank (start it without mpirun, or with mpirun -np 1)")


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

    code, output = mpirun(2, args.deepdraw, "two", work)
    if code != 2:
        failures.append(f"two ranks: exit code {code}, expected 2")
    if output.count(MESSAGE) != 1:
        failures.append(f"two ranks: the message {output.count(MESSAGE)} "
                        "times, expected once")
    if (work / "two").exists():
        failures.append("two ranks: the output folder was created")

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
