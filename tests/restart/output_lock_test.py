#!/usr/bin/env python3
"""One output folder, one run (doc/user_guide.md §6, doc/decisions.md D162,
D163): while a run lives, a second run and a --resume in its output
directory are refused with exit code 2 naming its process id, and nothing
in the folder changes; SIGHUP ends the run as SIGTERM does (exit code 3, a
checkpoint, the lock file removed), and the resumed run writes the tables
of the uninterrupted run; SIGQUIT too; a lock file left by a process that
is gone (SIGKILL) is taken over with a note on stdout, and removed at the
end.
"""
import os
import pathlib
import signal
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402

PRM = pathlib.Path(__file__).with_name("short_cup.prm")
LOCK = ".deepdraw.lock"


def start(args, work, output, *extra):
    return subprocess.Popen([args.deepdraw, str(PRM), "--output-directory",
                             str(output), *extra], cwd=work,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)


def run(args, work, output, *extra):
    result = subprocess.run([args.deepdraw, str(PRM), "--output-directory",
                             str(output), *extra], cwd=work,
                            capture_output=True, text=True)
    print("  exit %d: %s" % (result.returncode, result.stderr.strip()[:300]))
    return result


def rows(path):
    try:
        return sum(1 for _ in open(path)) - 1
    except FileNotFoundError:
        return -1


def wait_for_rows(process, output, n):
    deadline = time.time() + 120
    while rows(output / "statistics.csv") < n:
        if process.poll() is not None or time.time() > deadline:
            sys.exit("FAILED: the run ended before increment %d" % n)
        time.sleep(0.002)


def wait_until_stopped(pid):
    """Waits until every thread of process pid is stopped: SIGSTOP is
    delivered asynchronously, and a snapshot taken before the stop would see
    the run still writing (the failure of a loaded CI machine)."""
    deadline = time.time() + 60
    tasks = pathlib.Path("/proc/%d/task" % pid)
    while time.time() < deadline:
        states = []
        for task in tasks.iterdir():
            try:
                stat = (task / "stat").read_text()
            except FileNotFoundError:
                continue
            states.append(stat[stat.rindex(")") + 2])
        if states and all(state in "Tt" for state in states):
            return
        time.sleep(0.002)
    sys.exit("FAILED: the run did not stop on SIGSTOP within 60 s")


def stop_with(args, work, output, signal_number, name, failures):
    """Starts a run, signals it after 3 increments; checks its end."""
    process = start(args, work, output)
    wait_for_rows(process, output, 3)
    process.send_signal(signal_number)
    out, err = process.communicate(timeout=120)
    print("  %s: exit %d: %s" % (name, process.returncode, err.strip()))
    if process.returncode != 3 or "stopped by " + name not in err \
            or "--resume" not in err:
        failures.append("%s: exit %d, %s" % (name, process.returncode, err))
    if not (output / "checkpoint.bin").exists():
        failures.append("%s: no checkpoint" % name)
    if (output / LOCK).exists():
        failures.append("%s: the lock file was left behind" % name)


def main():
    args, _, work = script_test.start(__doc__)
    failures = []
    reference = work / "uninterrupted"
    if run(args, work, reference).returncode != 0:
        sys.exit("FAILED: the uninterrupted run")
    if (reference / LOCK).exists():
        failures.append("the lock file was left after a run")

    # A living run's folder: a second run and a --resume are refused.
    busy = work / "busy"
    process = start(args, work, busy)
    wait_for_rows(process, busy, 2)
    # Held still (the lock stays held) while the other runs try.
    process.send_signal(signal.SIGSTOP)
    wait_until_stopped(process.pid)
    if not (busy / LOCK).exists():
        failures.append("no lock file in a living run's folder")
    for extra in ((), ("--resume",)):
        before = script_test.snapshot(busy)
        result = run(args, work, busy, *extra)
        after = script_test.snapshot(busy)
        if after != before:
            failures.append("the refused run %s changed the folder"
                            % (extra,))
        if result.returncode != 2 \
                or "in use by deepdraw process %d" % process.pid \
                not in result.stderr:
            failures.append("a second run %s on a living run's folder: exit "
                            "%d: %s" % (extra, result.returncode,
                                        result.stderr))
    # SIGHUP: a clean stop with a checkpoint, resumed to the same tables.
    process.send_signal(signal.SIGHUP)
    process.send_signal(signal.SIGCONT)
    out, err = process.communicate(timeout=120)
    print("  SIGHUP: exit %d: %s" % (process.returncode, err.strip()))
    if process.returncode != 3 or "stopped by SIGHUP" not in err:
        failures.append("SIGHUP: exit %d, %s" % (process.returncode, err))
    if (busy / LOCK).exists():
        failures.append("SIGHUP: the lock file was left behind")
    result = run(args, work, busy, "--resume")
    if result.returncode != 0:
        failures.append("the run stopped by SIGHUP did not resume")
    failures += script_test.same_tables(reference, busy)

    stop_with(args, work, work / "quit", signal.SIGQUIT, "SIGQUIT", failures)
    stop_with(args, work, work / "term", signal.SIGTERM, "SIGTERM", failures)

    # A run killed with SIGKILL leaves its lock file; the resume takes it
    # over and ends as the uninterrupted run.
    killed = work / "killed"
    process = start(args, work, killed)
    wait_for_rows(process, killed, 2)
    process.kill()
    process.communicate(timeout=120)
    if not (killed / LOCK).exists():
        failures.append("SIGKILL: no lock file left to take over")
    result = run(args, work, killed, "--resume")
    if result.returncode != 0 or "taking over the stale lock %s" \
            % (killed / LOCK) not in result.stdout:
        failures.append("the resume after SIGKILL: exit %d, %s"
                        % (result.returncode, result.stdout[:300]))
    failures += script_test.same_tables(reference, killed)

    # A stale lock with an owner line: its process is gone.
    gone = subprocess.Popen(["true"])
    gone.wait()
    stale = work / "stale"
    stale.mkdir()
    (stale / LOCK).write_text("%d %s\n" % (gone.pid, os.uname().nodename))
    result = run(args, work, stale)
    if result.returncode != 0 or \
            "taking over the stale lock %s of process %d" \
            % (stale / LOCK, gone.pid) not in result.stdout:
        failures.append("a stale lock: exit %d, %s"
                        % (result.returncode, result.stdout[:500]))
    if (stale / LOCK).exists():
        failures.append("the taken-over lock was left behind")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
