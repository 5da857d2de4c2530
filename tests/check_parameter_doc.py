#!/usr/bin/env python3
"""Fails when doc/parameters.md is not what scripts/generate_parameter_doc.sh
writes for the given deepdraw executable (a parameter was added or changed
without regenerating the reference). Fix: rerun the script and commit the
result."""
import argparse
import difflib
import pathlib
import subprocess
import sys


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--deepdraw", required=True)
    parser.add_argument("--doc", required=True)
    args = parser.parse_args()

    script = (pathlib.Path(__file__).resolve().parent.parent
              / "scripts" / "generate_parameter_doc.sh")
    run = subprocess.run(["bash", str(script), args.deepdraw, "-"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
    if run.returncode != 0:
        sys.exit("FAILED: %s exited with code %d:\n%s"
                 % (script.name, run.returncode, run.stderr))

    doc = pathlib.Path(args.doc)
    current = doc.read_text() if doc.exists() else ""
    if current == run.stdout:
        print("PASSED: %s is up to date" % doc)
        return
    sys.stdout.writelines(difflib.unified_diff(
        current.splitlines(keepends=True), run.stdout.splitlines(keepends=True),
        fromfile=str(doc), tofile="generated"))
    sys.exit("\nFAILED: %s is out of date; run scripts/generate_parameter_doc.sh "
             "(after building) and commit the result" % doc)


if __name__ == "__main__":
    main()
