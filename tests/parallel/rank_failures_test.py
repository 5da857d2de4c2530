#!/usr/bin/env python3
"""Failures under mpirun (issue 29, D199), each with 2 ranks: the reason is
printed once, the exit code is the one-rank run's, and no rank is left
waiting.
- Input errors found by every rank (a parameter out of range, KLU, which
  runs on one rank, UMFPACK and the decoupled unknowns left out, which need
  the whole matrix on one rank (D214), --study): exit 2, the message once,
  nothing written.
- An input error found by rank 0 alone (the output directory is a regular
  file; only rank 0 makes and locks it): exit 2 once, the other rank does
  not hang (the start-up agreement).
- SIGTERM to mpirun, which passes it on to every rank at its own time: the
  ranks stop at the same increment with the reason once and a checkpoint
  (mpirun, signalled itself, exits with its own code); --resume with 2
  ranks ends the run with the tables of the uninterrupted 2-rank run within
  1e-8 (ranks_agree_test's bound).
- SIGTERM to one rank only (as a batch system may send it): the ranks stop
  at the same increment and every rank ends with 3.
- SIGKILL to rank 1, then to rank 0, of a running 2-rank job: mpirun ends
  the job (measured: exit code 137 within 2 s), every table ends with a
  whole row, and --resume on 2 ranks from what is on disk ends with the
  uninterrupted 2-rank run's tables within 1e-8.
- A mesh that fits the memory for one rank but not for the 3 ranks of this
  machine, each of which holds the whole mesh (D209): exit 2 before any
  mesh is made, the message once, naming the ranks and the memory they
  need together, which is the one-rank estimate of D53 (computed here from
  its published constants) times 3 (1 - f) + f with MUMPS' factor share
  f = 1/3 split over the ranks.
- A failure of rank 0 alone in the middle of the run (a VTU file it cannot
  write; only rank 0 writes): its reason once, exit code 3 within the
  ranks' patience (60 s), the tables on disk end with whole rows at 0.9 or
  1.0 mm.

    rank_failures_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import os
import pathlib
import re
import signal
import subprocess
import sys
import time

from mpirun_tools import SHORT_CUP, run, script_test, start

BAD_ELEMENTS = """include {base}
subsection Geometry
  set Elements along x = 0
end
"""

KLU = """include {base}
subsection Linear solver
  set Type = KLU
end
"""

UMFPACK = """include {base}
subsection Linear solver
  set Type = UMFPACK
end
"""

LEAVE_OUT = """include {base}
subsection Linear solver
  set Leave out decoupled unknowns = true
end
"""

# Slower, so that a signal finds it running: the same cup on 24 x 24 x 2.
FINER = """include {base}
subsection Geometry
  set Elements along x = 24
  set Elements along y = 24
end
subsection Output
  set Output interval = 10
end
"""


def once(failures, what, output, text, code, expected_code):
    print(f"{what}: exit code {code}, {output.count(text)} x '{text}'")
    if code != expected_code:
        failures.append(f"{what}: exit code {code}, expected "
                        f"{expected_code}")
    if output.count(text) != 1:
        failures.append(f"{what}: '{text}' printed {output.count(text)} "
                        "times, expected once")


def input_errors(failures, args, work):
    (work / "bad.prm").write_text(BAD_ELEMENTS.format(base=SHORT_CUP))
    (work / "klu.prm").write_text(KLU.format(base=SHORT_CUP))
    (work / "umfpack.prm").write_text(UMFPACK.format(base=SHORT_CUP))
    (work / "leave_out.prm").write_text(LEAVE_OUT.format(base=SHORT_CUP))
    cases = [("a parameter out of range", ["bad.prm"], "bad"),
             ("KLU", ["klu.prm"], "klu"),
             ("UMFPACK", ["umfpack.prm"], "umfpack"),
             ("decoupled unknowns left out", ["leave_out.prm"], "leave_out"),
             ("--study", [SHORT_CUP, "--study", "Geometry/Layers = 2, 4"],
              "study")]
    for what, arguments, output in cases:
        code, printed = run(2, args.deepdraw, work, *arguments,
                            "--output-directory", output, timeout=120)
        once(failures, what, printed, "deepdraw: error in the input:", code,
             2)
        if (work / output).exists():
            failures.append(f"{what}: the output directory was made")
    (work / "a_file").write_text("not a directory\n")
    code, printed = run(2, args.deepdraw, work, SHORT_CUP,
                        "--output-directory", "a_file", timeout=120)
    once(failures, "the output directory a regular file", printed,
         "deepdraw: error in the input:", code, 2)


def available_memory():
    """MemAvailable, limited by the cgroup as deepdraw limits it."""
    for line in open("/proc/meminfo"):
        if line.startswith("MemAvailable:"):
            available = int(line.split()[1]) * 1024
    try:
        limit = pathlib.Path("/sys/fs/cgroup/memory.max").read_text().strip()
        current = int(pathlib.Path("/sys/fs/cgroup/memory.current")
                      .read_text())
        if limit != "max":
            available = min(available, max(0, int(limit) - current))
    except (OSError, ValueError):
        pass
    return available


def one_rank_estimate(n):
    """D53's estimate for the short cup on n x n x 2 cells: 170 MB, 48 kB a
    cell, 19 kB a contact pair (3 tools, a pair per node of a face)."""
    return 170e6 + 48e3 * 2 * n * n + 19e3 * 3 * (n + 1) ** 2


def memory_of_the_machine(failures, args, work):
    # The largest square mesh whose one-rank estimate is at most 55 % of
    # the memory: one rank would be let run, 3 ranks need 2.33 times it.
    budget = 0.55 * available_memory()
    n = 1
    while one_rank_estimate(n + 1) <= budget:
        n += 1
    (work / "memory.prm").write_text(
        f"include {SHORT_CUP}\nsubsection Geometry\n"
        f"  set Elements along x = {n}\n  set Elements along y = {n}\nend\n")
    # A refusal takes about a second; a run that was let start is killed
    # before its mesh fills the memory.
    try:
        code, printed = run(3, args.deepdraw, work, "memory.prm",
                            "--output-directory", "memory", timeout=60)
    except subprocess.TimeoutExpired:
        failures.append(f"memory of 3 ranks: the {n} x {n} x 2 mesh was not "
                        "refused")
        return
    once(failures, "memory of 3 ranks on one machine", printed,
         "deepdraw: error in the input:", code, 2)
    expected = one_rank_estimate(n) * (3 * (1 - 1 / 3) + 1 / 3) / 1e9
    found = re.search(r"needs about ([0-9.e+]+) GB of memory on this machine "
                      r"for its 3 MPI ranks", printed)
    print(f"{n} x {n} x 2: expected {expected:.4g} GB, message "
          f"{found.group(1) if found else None}")
    # The message prints 3 significant digits.
    if not found or abs(float(found.group(1)) - expected) > 0.0051 * expected:
        failures.append(f"memory of 3 ranks: expected about {expected:.3g} "
                        "GB in the message")
    if (work / "memory").exists():
        failures.append("memory of 3 ranks: the output directory was made")


def wait_for_lines(process, path, n):
    """Waits until the table at path has n lines; False if the process
    ended first or 300 s passed."""
    deadline = time.time() + 300
    while not path.exists() or len(path.read_text().splitlines()) < n:
        if process.poll() is not None or time.time() > deadline:
            return False
        time.sleep(0.01)
    return True


def tables_end_whole(failures, directory, what):
    for table in directory.glob("*.csv"):
        if not table.read_text().endswith("\n"):
            failures.append(f"{what}: {table.name} does not end with a whole "
                            "row")


def signal_and_resume(failures, args, work):
    (work / "finer.prm").write_text(FINER.format(base=SHORT_CUP))
    code, _ = run(2, args.deepdraw, work, "finer.prm", "--output-directory",
                  "whole", "--quiet")
    if code != 0:
        failures.append(f"the 2-rank run to compare with: exit code {code}")
        return
    process = start(2, args.deepdraw, work, "finer.prm",
                    "--output-directory", "stopped")
    statistics = work / "stopped" / "statistics.csv"
    if not wait_for_lines(process, statistics, 5):
        failures.append("the run to be stopped ended or hung")
        return
    process.send_signal(signal.SIGTERM)
    printed, _ = process.communicate(timeout=120)
    print(printed[-1500:])
    # mpirun, signalled itself, ends with its own code (1 in Open MPI 4.1).
    once(failures, "SIGTERM to mpirun", printed, "deepdraw: the run stopped: "
         "stopped by SIGTERM", max(process.returncode, 1), 1)
    # A signal to rank 0 alone (as a batch system may send): the ranks
    # agree to stop at the same increment, and each ends with 3.
    process = start(2, args.deepdraw, work, "finer.prm",
                    "--output-directory", "stopped", "--resume")
    stopped_at = len(statistics.read_text().splitlines())
    # One increment after the resume, six before the end: time enough for
    # the signal to arrive before the last increment.
    if not wait_for_lines(process, statistics, stopped_at + 1):
        failures.append("the resumed run to be stopped ended or hung")
        return
    # The newest of the ranks (not mpirun, whose command line begins with
    # its own name).
    subprocess.run(["pkill", "-TERM", "-n", "-f",
                    "^[^ ]*deepdraw finer.prm --output-directory stopped"])
    printed, _ = process.communicate(timeout=120)
    print(printed[-1500:])
    once(failures, "SIGTERM to one rank", printed, "deepdraw: the run "
         "stopped: stopped by SIGTERM", process.returncode, 3)
    code, _ = run(2, args.deepdraw, work, "finer.prm", "--output-directory",
                  "stopped", "--resume", "--quiet")
    if code != 0:
        failures.append(f"the resume with 2 ranks: exit code {code}")
        return
    failures += script_test.close_tables(work / "whole", work / "stopped",
                                         "the uninterrupted 2-rank run",
                                         relative=1e-8)


def rank_process(pattern, rank):
    """The process id of a rank: of the processes whose command line
    matches pattern (mpirun's begins with its own name, not deepdraw's), the
    one Open MPI gave OMPI_COMM_WORLD_RANK=rank."""
    listed = subprocess.run(["pgrep", "-f", pattern], capture_output=True,
                            text=True).stdout.split()
    for pid in map(int, listed):
        try:
            environment = pathlib.Path(f"/proc/{pid}/environ").read_bytes()
        except OSError:
            continue
        if f"OMPI_COMM_WORLD_RANK={rank}".encode() in environment.split(b"\0"):
            return pid
    sys.exit(f"FAILED: no process of rank {rank} among {listed}")


def killed_rank(failures, args, work, victim):
    """SIGKILL to one rank (victim: 'rank 0' or 'rank 1') of a 2-rank run
    of finer.prm: the job ends without hanging, every table on disk ends
    with a whole row, and --resume on 2 ranks from what is on disk (the
    checkpoint of the last whole increment and the stale lock left by a
    killed rank 0) ends with the uninterrupted run's tables within 1e-8."""
    output = "killed_" + victim.replace(" ", "_")
    process = start(2, args.deepdraw, work, "finer.prm",
                    "--output-directory", output)
    if not wait_for_lines(process, work / output / "statistics.csv", 5):
        failures.append(f"SIGKILL to {victim}: the run ended or hung "
                        "before the signal")
        return
    pattern = "^[^ ]*deepdraw finer.prm --output-directory " + output
    os.kill(rank_process(pattern, int(victim.split()[-1])), signal.SIGKILL)
    began = time.time()
    try:
        printed, _ = process.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        process.kill()
        subprocess.run(["pkill", "-KILL", "-f", pattern])
        failures.append(f"SIGKILL to {victim}: the job hung")
        return
    print(printed[-800:])
    print(f"SIGKILL to {victim}: mpirun exit code {process.returncode} "
          f"after {time.time() - began:.1f} s")
    if process.returncode == 0:
        failures.append(f"SIGKILL to {victim}: exit code 0")
    tables_end_whole(failures, work / output, f"SIGKILL to {victim}")
    code, _ = run(2, args.deepdraw, work, "finer.prm", "--output-directory",
                  output, "--resume", "--quiet")
    if code != 0:
        failures.append(f"SIGKILL to {victim}: the resume ended with {code}")
        return
    failures += script_test.close_tables(
        work / "whole", work / output,
        f"the uninterrupted 2-rank run, after SIGKILL to {victim}",
        relative=1e-8)


def rank_zero_alone(failures, args, work):
    # Where rank 0 writes its piece of the VTU of load 1.0
    # (solution-00002.0.vtu, through a temporary file) a directory stands:
    # only rank 0 fails, at 1.0, while rank 1 waits for the pieces.
    (work / "blocked" / "solution-00002.0.vtu.tmp").mkdir(parents=True)
    began = time.time()
    code, printed = run(2, args.deepdraw, work, SHORT_CUP,
                        "--output-directory", "blocked", timeout=300)
    took = time.time() - began
    print(f"exit code {code} after {took:.1f} s")
    once(failures, "rank 0 failing alone", printed,
         "deepdraw: the run stopped:", code, 3)
    if took > 120:
        failures.append(f"the job took {took:.0f} s to end")
    rows = script_test.csv_rows(work / "blocked" / "punch_force.csv")
    # The increment at 1.0 converged; its outputs stop at the VTU.
    last = rows[-1]["punch_travel_mm"] if rows else None
    print(f"punch_force.csv ends at {last} mm")
    if last is None or not 0.9 - 1e-9 <= last <= 1.0 + 1e-9:
        failures.append(f"punch_force.csv ends at {last}, expected 0.9 or "
                        "1.0 mm")
    tables_end_whole(failures, work / "blocked", "rank 0 failing alone")


def main():
    args, _, work = script_test.start(__doc__)
    failures = []
    input_errors(failures, args, work)
    memory_of_the_machine(failures, args, work)
    signal_and_resume(failures, args, work)
    killed_rank(failures, args, work, "rank 1")
    killed_rank(failures, args, work, "rank 0")
    rank_zero_alone(failures, args, work)
    script_test.finish(failures)


if __name__ == "__main__":
    main()
