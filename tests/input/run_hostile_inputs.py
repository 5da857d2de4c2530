#!/usr/bin/env python3
"""Hostile input as a test suite (doc/user_guide.md §5.2): runs the cases of
one class of tests/input/hostile_cases.py through the deepdraw executable,
each in a fresh directory, and asserts for every case

  * the exit code (1 command line, 2 bad input, 3 the run stopped);
  * every expected part of the message, on stderr, which for exit codes 2
    and 3 is exactly one line (no muparser or deal.II lines before it);
  * that everything deepdraw printed is printable UTF-8 (no bytes of a
    binary input echoed);
  * for exit code 2: no output directory; for exit code 3: no *.tmp file
    left, every CSV file ends with a whole row of the header's width, and
    no CSV value is nan or inf.

Prints one line per case and the number of cases; exits non-zero if one
failed. A case may be skipped where the machine cannot produce it (a tiny
file system needs root); the skip is printed.

  run_hostile_inputs.py --deepdraw EXE --source-dir REPO --work-dir DIR --class NAME
                        [--jobs N] [--launcher "mpirun --oversubscribe -np 2"]

With --launcher every case runs under it (tests/parallel, D199): the same
exit codes and the message printed once, not once per rank; mpirun's own
notices are left out of what is checked.
"""
import argparse
import concurrent.futures
import os
import pathlib
import re
import shutil
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]
                       / "parallel"))
import hostile_cases  # noqa: E402
import mpirun_tools  # noqa: E402  (tests/parallel/mpirun_tools.py)


def printable(text):
    """True if text has no control characters except newline and tab."""
    return all(c in "\n\t" or (ord(c) >= 0x20 and ord(c) != 0x7F)
               for c in text)


def check_outputs(output):
    """Problems of an output directory left by a run that stopped."""
    problems = []
    if not output.is_dir():
        return problems
    for path in sorted(output.iterdir()):
        if path.name.endswith(".tmp"):
            problems.append("temporary file left: " + path.name)
        if path.suffix != ".csv":
            continue
        data = path.read_bytes()
        if data and not data.endswith(b"\n"):
            problems.append(path.name + " ends inside a row")
        lines = data.decode("utf-8", "replace").splitlines()
        if not lines:
            continue
        width = len(lines[0].split(","))
        for number, line in enumerate(lines[1:], 2):
            values = line.split(",")
            if len(values) != width:
                problems.append("%s:%d has %d values, the header %d"
                                % (path.name, number, len(values), width))
            if any(v.strip().lower().lstrip("+-") in ("nan", "inf")
                   for v in values):
                problems.append("%s:%d holds nan or inf" % (path.name, number))
    return problems


def without_launcher_text(text):
    """What deepdraw printed, without mpirun's own notices (blocks between
    lines of dashes, and lines tagged [host:pid]) and without the warning
    that the event library of Open MPI's runtime prints now and then when a
    rank's output closes as it exits ("[warn] Epoll MOD(1) on fd 24
    failed ... Bad file descriptor"; open-mpi/ompi issues 2004 and 5520,
    D207)."""
    kept, inside = [], False
    for line in text.splitlines():
        if len(line) > 20 and set(line.strip()) == {"-"}:
            inside = not inside
            continue
        if not inside and not re.match(r"\[\S+:\d+\] |\[warn\] Epoll ",
                                       line):
            kept.append(line)
    return "\n".join(kept) + ("\n" if kept else "")


def run_case(case, deepdraw, source, work, launcher=()):
    """Returns (status, detail): status 'ok', 'FAIL' or 'skip'. Under a
    launcher (mpirun) the cases that set limits of the process are
    skipped: the limits would hold for mpirun's own files too."""
    if launcher and "preexec" in case:
        return "skip", "sets process limits, not under mpirun"
    if launcher and "--study" in case.get("args", []):
        return "skip", "--study runs on one rank (tests/parallel)"
    directory = work / case["name"]
    if directory.exists():
        shutil.rmtree(directory)
    directory.mkdir(parents=True)
    (directory / "prm").symlink_to(source / "prm", target_is_directory=True)
    for name, content in case.get("files", {}).items():
        path = directory / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(content if isinstance(content, bytes)
                         else content.encode("utf-8"))
    context = {"directory": directory, "source": source}
    if "setup" in case:
        reason = case["setup"](context)
        if reason:
            return "skip", reason
    try:
        arguments = case.get("args", ["case.prm", "--output-directory",
                                      "output"])
        command = list(launcher) + [deepdraw] + \
            [a.format(**context) for a in arguments]
        run = subprocess.run(command, cwd=directory, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, timeout=300,
                             preexec_fn=case.get("preexec"),
                             env=mpirun_tools.environment())
    finally:
        if "cleanup" in case:
            case["cleanup"](context)
    problems = []
    try:
        out = run.stdout.decode("utf-8")
        err = run.stderr.decode("utf-8")
        if launcher:
            out = without_launcher_text(out)
            err = without_launcher_text(err)
    except UnicodeDecodeError:
        return "FAIL", "deepdraw printed bytes that are not UTF-8"
    if not printable(out + err):
        problems.append("deepdraw printed control characters")
    if run.returncode != case["exit"]:
        problems.append("exit code %d, expected %d" % (run.returncode,
                                                       case["exit"]))
    expected = case.get("messages", [])
    if launcher:
        expected = case.get("launcher_messages", expected)
    for part in expected:
        if part not in err:
            problems.append("message lacks '%s'" % part)
    if case["exit"] in (2, 3):
        lines = [line for line in err.splitlines() if line.strip()]
        if len(lines) != 1:
            problems.append("%d lines on stderr, expected one" % len(lines))
    output = directory / case.get("output", "output")
    if case["exit"] == 2 and case.get("output", "output") and output.exists():
        problems.append("a rejected input created " + output.name)
    if case["exit"] == 3:
        problems += check_outputs(output)
    if "check" in case:
        problems += case["check"](context)
    detail = err.strip().splitlines()[-1] if err.strip() else "(no message)"
    if problems:
        return "FAIL", "; ".join(problems) + " | " + detail[:400]
    return "ok", detail[:200]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--deepdraw", required=True)
    parser.add_argument("--source-dir", required=True)
    parser.add_argument("--work-dir", required=True)
    parser.add_argument("--class", dest="case_class", required=True,
                        choices=sorted(hostile_cases.CLASSES))
    parser.add_argument("--jobs", type=int, default=4,
                        help="cases run at the same time (default 4)")
    parser.add_argument("--launcher", default="",
                        help="a command deepdraw is started under, such as "
                        "'mpirun --oversubscribe -np 2' (tests/parallel)")
    args = parser.parse_args()
    source = pathlib.Path(args.source_dir).resolve()
    work = pathlib.Path(args.work_dir).resolve()
    work.mkdir(parents=True, exist_ok=True)
    deepdraw = str(pathlib.Path(args.deepdraw).resolve())

    cases = hostile_cases.CLASSES[args.case_class](source)
    # Several cases at once: a deepdraw process spends about half of its
    # start waiting for MPI, not computing (D54).
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(
            lambda case: run_case(case, deepdraw, source, work,
                                  args.launcher.split()), cases))
    failed = skipped = 0
    for case, (status, detail) in zip(cases, results):
        failed += status == "FAIL"
        skipped += status == "skip"
        print("  %-4s %s: %s" % (status, case["name"], detail), flush=True)
    print("%s: %d cases, %d failed, %d skipped"
          % (args.case_class, len(cases), failed, skipped))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
