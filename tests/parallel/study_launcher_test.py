#!/usr/bin/env python3
"""A study whose runs start under mpirun (issue 29, D200): with
DEEPDRAW_MPI_LAUNCHER="mpirun --oversubscribe -np 2" in the environment,
`deepdraw FILE.prm --study ...` (itself started without mpirun) runs each
case as `mpirun ... deepdraw`; each run's console says it ran on 2 MPI
ranks, and study.csv holds the values of the same study run without the
launcher within 1e-8 (ranks_agree_test's bound for 1 against 2 ranks). A
launcher that is not a program is refused: exit 2, one line naming the
variable, nothing written.

    study_launcher_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import subprocess

from mpirun_tools import SHORT_CUP, environment, script_test

STUDY = ["--study", "Geometry/Elements along x = 6, 8"]


def study(args, work, output, launcher):
    env = environment()
    env.pop("DEEPDRAW_MPI_LAUNCHER", None)
    if launcher is not None:
        env["DEEPDRAW_MPI_LAUNCHER"] = launcher
    command = [args.deepdraw, str(SHORT_CUP), *STUDY, "--output-directory",
               output]
    print("running:", " ".join(command), "with DEEPDRAW_MPI_LAUNCHER =",
          launcher, flush=True)
    result = subprocess.run(command, cwd=work, env=env, text=True,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            timeout=600)
    print(result.stdout[-1500:], result.stderr[-1500:])
    return result


def main():
    args, _, work = script_test.start(__doc__)
    failures = []
    plain = study(args, work, "plain", None)
    launched = study(args, work, "launched",
                     "mpirun --oversubscribe -np 2")
    for name, result in (("without", plain), ("with", launched)):
        if result.returncode != 0:
            failures.append(f"the study {name} the launcher: exit code "
                            f"{result.returncode}")
    if not failures:
        for run in sorted((work / "launched").glob("run_*")):
            log = (run / "deepdraw.log").read_text()
            if "2 MPI ranks" not in log:
                failures.append(f"{run.name}: its console does not say "
                                "'2 MPI ranks'")
        failures += script_test.close_tables(work / "plain",
                                             work / "launched",
                                             "the study without launcher",
                                             relative=1e-8)

    bad = study(args, work, "refused", "no_such_launcher -np 2")
    lines = [line for line in bad.stderr.splitlines() if line.strip()]
    print(f"no such launcher: exit code {bad.returncode}, {lines}")
    if bad.returncode != 2 or len(lines) != 1 or \
            "DEEPDRAW_MPI_LAUNCHER" not in lines[0]:
        failures.append("a launcher that is not a program: not one line "
                        "naming DEEPDRAW_MPI_LAUNCHER with exit code 2")
    if (work / "refused").exists():
        failures.append("the refused study made its output directory")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
