#!/usr/bin/env python3
"""Bad --study options and bad input of a study (doc/user_guide.md §4.2,
doc/decisions.md D41): each must end with exit code 2, a message naming
the problem, and no output directory."""
import argparse
import pathlib
import shutil
import subprocess
import sys

parser = argparse.ArgumentParser()
parser.add_argument("--deepdraw", required=True)
parser.add_argument("--source-dir", required=True)
parser.add_argument("--work-dir", required=True)
args = parser.parse_args()

work = pathlib.Path(args.work_dir)
if work.exists():
    shutil.rmtree(work)
work.mkdir(parents=True)
source = pathlib.Path(args.source_dir).resolve()
bar = str(source / "prm" / "tension_bar.prm")
layers = "Geometry/Layers through thickness"

# (prm, --study options, expected piece of the message)
cases = [
    (bar, ["Geometry/Layers = 1, 2"],
     "Geometry/Layers is not a parameter"),
    (bar, ["Geometri/Layers through thickness = 1, 2"],
     "Geometri/Layers through thickness is not a parameter"),
    (bar, ["Geometry = 1, 2"], "Geometry is not a parameter"),
    (bar, ["Contact/Tool 1 = 1, 2"], "Contact/Tool 1 is not a parameter"),
    (bar, [layers], "expected 'Subsection/Parameter = value, value, ...'"),
    (bar, ["/Layers through thickness = 1"],
     "is not of the form Subsection/Parameter"),
    (bar, ["Geometry//Layers through thickness = 1"],
     "is not of the form Subsection/Parameter"),
    (bar, [layers + " = "], "no values for " + layers),
    (bar, [layers + " = 1, , 2"], "value 2 of " + layers + " is empty"),
    (bar, [layers + " = 1, 2,"], "value 3 of " + layers + " is empty"),
    (bar, ["Geometry/Elements along x = 2, 3",
           "Geometry/Elements along y = 2, 3, 4"],
     "3 values, but Geometry/Elements along x has 2"),
    (bar, [layers + " = 1, 2", layers + " = 3, 4"],
     layers + " is varied by two --study options"),
    (bar, ["Output/Output directory = a, b"],
     "the study sets the output directory of each run"),
    (str(work / "no_such_file.prm"), [layers + " = 1, 2"],
     "cannot open the parameter file"),
    (str(source / "tests" / "input" / "unknown_parameter.prm"),
     [layers + " = 1, 2"], "No entry with name"),
]

failed = 0
for k, (prm, options, message) in enumerate(cases):
    output = work / ("output_%d" % k)
    command = [args.deepdraw, prm, "--output-directory", str(output)]
    for option in options:
        command += ["--study", option]
    run = subprocess.run(command, cwd=work, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    problems = []
    if run.returncode != 2:
        problems.append("exit code %d, expected 2" % run.returncode)
    if message not in run.stderr:
        problems.append("the message does not contain: " + message)
    if output.exists():
        problems.append("created " + str(output))
    print(("  FAIL " if problems else "  ok   ") + repr(options) + ": "
          + run.stderr.strip() + ("" if not problems else " <- " + "; ".join(problems)))
    failed += bool(problems)
if failed:
    sys.exit("FAILED: %d of %d cases" % (failed, len(cases)))
print("PASSED: %d cases" % len(cases))
