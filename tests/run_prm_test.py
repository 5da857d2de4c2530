#!/usr/bin/env python3
"""Runs one prm-driven test (see tests/CMakeLists.txt for the conventions).

The prm file is run with deepdraw in a fresh work directory; its
'Output directory' is overridden to <work-dir>/output so tests never write
into the source tree. With --source-dir, the work directory gets a link
prm -> <source-dir>/prm, so that a test can `include prm/<shipped>.prm`
(ParameterHandler opens include files relative to the working directory;
the same line works when deepdraw is started from the repository root, as
in doc/user_guide.md) and a broken shipped prm fails its tests. If present
next to the prm:
  <name>.args            more command-line arguments, one per line (a line
                         is one argument, spaces included), e.g. --study
                         options;
  <name>.exit_code       the exit code the run must end with (default 0;
                         the checks below still run).
Then, in this order and if present next to the prm:
  <name>.expected_error  the run must fail (non-zero exit), its output must
                         contain every non-empty line of this file, and the
                         output directory must not have been created;
  <name>.check.py        called as: python3 check.py <output-dir> in the
                         work directory, with the executable in the
                         environment variable DEEPDRAW; it asserts the
                         physics and exits non-zero on failure;
  <name>.reference/      every file in it is compared with the output file of
                         the same name by numdiff, with the tolerances given
                         in <name>.reference/NUMDIFF (one line of options).
"""
import argparse
import os
import pathlib
import shutil
import subprocess
import sys


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--deepdraw", required=True)
    parser.add_argument("--prm", required=True)
    parser.add_argument("--work-dir", required=True)
    parser.add_argument("--source-dir",
                        help="repository root: its prm/ is linked into the "
                             "work directory for `include prm/...`")
    parser.add_argument("--expected-error",
                        help="file with the expected error lines (default: "
                             "<name>.expected_error next to the prm)")
    args = parser.parse_args()

    # Absolute: deepdraw runs in the work directory.
    prm = pathlib.Path(args.prm).resolve()
    stem = prm.with_suffix("")
    work = pathlib.Path(args.work_dir)
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    if args.source_dir:
        (work / "prm").symlink_to(pathlib.Path(args.source_dir).resolve() / "prm",
                                  target_is_directory=True)
    output = work / "output"

    command = [args.deepdraw, str(prm), "--output-directory", str(output)]
    extra = pathlib.Path(str(stem) + ".args")
    if extra.exists():
        command += [line for line in extra.read_text().splitlines()
                    if line.strip()]
    exit_code_file = pathlib.Path(str(stem) + ".exit_code")
    expected_code = (int(exit_code_file.read_text())
                     if exit_code_file.exists() else 0)
    print("running:", " ".join(command), flush=True)
    run = subprocess.run(command, cwd=work, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    print(run.stdout)

    expected_error = pathlib.Path(args.expected_error or
                                  str(stem) + ".expected_error")
    if expected_error.exists():
        if run.returncode == 0:
            sys.exit("FAILED: the run succeeded but was expected to fail")
        for line in expected_error.read_text().splitlines():
            if line.strip() and line.strip() not in run.stdout:
                sys.exit("FAILED: the message does not contain: " + line)
        if output.exists():
            sys.exit("FAILED: a rejected input still created " + str(output))
        print("PASSED: the run failed with the expected message")
        return

    if run.returncode != expected_code:
        sys.exit("FAILED: deepdraw exited with code %d, expected %d"
                 % (run.returncode, expected_code))

    check = pathlib.Path(str(stem) + ".check.py")
    if check.exists():
        result = subprocess.run([sys.executable, str(check), str(output)],
                                cwd=work,
                                env=dict(os.environ, DEEPDRAW=args.deepdraw))
        if result.returncode != 0:
            sys.exit("FAILED: " + check.name)

    reference = pathlib.Path(str(stem) + ".reference")
    if reference.is_dir():
        options_file = reference / "NUMDIFF"
        options = options_file.read_text().split() if options_file.exists() else []
        for expected in sorted(reference.iterdir()):
            if expected.name == "NUMDIFF":
                continue
            result = subprocess.run(["numdiff", "-q"] + options +
                                    [str(expected), str(output / expected.name)])
            if result.returncode != 0:
                subprocess.run(["numdiff"] + options +
                               [str(expected), str(output / expected.name)])
                sys.exit("FAILED: numdiff " + expected.name)
    print("PASSED")


if __name__ == "__main__":
    main()
