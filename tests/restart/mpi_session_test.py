#!/usr/bin/env python3
"""Open MPI's session directory of a deepdraw process (doc/user_guide.md §1,
doc/decisions.md D99): started without mpirun, deepdraw runs the daemon-less
singleton under $TMPDIR/deepdraw-mpi-PID-XXXXXX, a base of its own, and
removes it when it ends; a base left by a killed process is removed by the
next start, one of a live process is not; concurrent starts do not share
one (D98 saw 2 of 120 fail when they did).

Expectations are the state of the file system and exit codes, so there is
no tolerance.
"""
import os
import pathlib
import signal
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402  (tests/script_test.py)

PRM = pathlib.Path(__file__).with_name("short_cup.prm")
PREFIX = "deepdraw-mpi-"


def bases(temporary):
    return sorted(p.name for p in temporary.iterdir()
                  if p.name.startswith(PREFIX))


def help_run(deepdraw, environment):
    return subprocess.run([deepdraw, "--help"], env=environment,
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                          text=True, timeout=120)


def main():
    args, _, work = script_test.start(__doc__)
    temporary = work / "tmp"
    temporary.mkdir()
    environment = dict(os.environ)
    environment["TMPDIR"] = str(temporary)
    for name in ("OMPI_MCA_orte_tmpdir_base", "OMPI_MCA_ess_singleton_isolated",
                 "DEEPDRAW_MPI_SESSION_BASE", "OMPI_COMM_WORLD_SIZE",
                 "PMIX_RANK"):
        environment.pop(name, None)
    failures = []

    # One start: its base is gone afterwards.
    result = help_run(args.deepdraw, environment)
    if result.returncode != 0:
        failures.append(f"--help exit {result.returncode}: {result.stderr}")
    if bases(temporary):
        failures.append(f"left behind after a normal end: {bases(temporary)}")

    # A base of an ended process is removed; one of a live process is kept.
    ended = subprocess.Popen(["true"])
    ended.wait()
    stale = temporary / f"{PREFIX}{ended.pid}-abcdef"
    (stale / "ompi.host.0" / "jf.0" / "1").mkdir(parents=True)
    live = temporary / f"{PREFIX}{os.getpid()}-abcdef"
    live.mkdir()
    help_run(args.deepdraw, environment)
    if stale.exists():
        failures.append("the base of an ended process was not removed")
    if not live.exists():
        failures.append("the base of a live process was removed")
    live.rmdir()

    # A running process has its own base, named after it; SIGKILL leaves
    # it, the next start removes it.
    process = subprocess.Popen([args.deepdraw, str(PRM), "--output-directory",
                                str(work / "killed")], env=environment,
                               cwd=work, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
    deadline = time.time() + 60
    own = []
    while not own and time.time() < deadline and process.poll() is None:
        own = [b for b in bases(temporary)
               if b.startswith(f"{PREFIX}{process.pid}-")]
        time.sleep(0.01)
    if not own:
        failures.append("no base named after the running process")
    process.send_signal(signal.SIGKILL)
    process.wait(timeout=60)
    if own and own[0] not in bases(temporary):
        failures.append("SIGKILL: the base is gone, so this test no longer "
                        "checks the clean-up of the next start")
    help_run(args.deepdraw, environment)
    if bases(temporary):
        failures.append(f"after SIGKILL and a new start: {bases(temporary)}")

    # A study's child inherits its parent's base and isolated mode in the
    # environment: it makes a base of its own all the same (sharing one is
    # what failed in D98).
    parent_base = temporary / f"{PREFIX}{os.getpid()}-parent"
    parent_base.mkdir()
    child_environment = dict(environment)
    child_environment.update({
        "OMPI_MCA_orte_tmpdir_base": str(parent_base),
        "DEEPDRAW_MPI_SESSION_BASE": str(parent_base),
        "OMPI_MCA_ess_singleton_isolated": "1"})
    child = subprocess.Popen([args.deepdraw, str(PRM), "--output-directory",
                              str(work / "child")], env=child_environment,
                             cwd=work, stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL)
    deadline = time.time() + 60
    own = []
    while not own and time.time() < deadline and child.poll() is None:
        own = [b for b in bases(temporary)
               if b.startswith(f"{PREFIX}{child.pid}-")]
        time.sleep(0.01)
    child.kill()
    child.wait(timeout=60)
    if not own:
        failures.append("a study's child ran under its parent's base")
    parent_base.rmdir()
    help_run(args.deepdraw, environment)

    # Concurrent starts: every one succeeds, nothing is left.
    starts = [subprocess.Popen([args.deepdraw, "--help"], env=environment,
                               stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, text=True)
              for _ in range(16)]
    for start in starts:
        _, err = start.communicate(timeout=120)
        if start.returncode != 0:
            failures.append(f"concurrent start exit {start.returncode}: "
                            f"{err.strip()[:200]}")
    if bases(temporary):
        failures.append(f"after concurrent starts: {bases(temporary)}")

    for failure in failures:
        print("FAILED:", failure)
    if failures:
        sys.exit(1)
    print("mpi_session: every base removed, concurrent starts all succeeded")


if __name__ == "__main__":
    main()
