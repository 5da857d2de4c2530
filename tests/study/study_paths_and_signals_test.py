#!/usr/bin/env python3
"""deepdraw --study started away from its prm, and stopped by a signal
(issue 32, doc/decisions.md D168, D179):

  * a prm in another directory with CAD tools and a blank outline named
    relative to it: every run finds them (input.prm names them absolutely),
    both rows "ok";
  * SIGINT to the study's process group (Ctrl-C) and SIGINT to the study
    alone during its first run: exit code 130, study.csv with the header
    and one row "interrupted", the run stopped cleanly (its checkpoint), the
    message naming the signal.

  study_paths_and_signals_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import argparse
import csv
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import time

parser = argparse.ArgumentParser()
parser.add_argument("--deepdraw", required=True)
parser.add_argument("--source-dir", required=True)
parser.add_argument("--work-dir", required=True)
args = parser.parse_args()
source = pathlib.Path(args.source_dir).resolve()
work = pathlib.Path(args.work_dir).resolve()
if work.exists():
    shutil.rmtree(work)
project = work / "project"
(project / "tools").mkdir(parents=True)
for tool in ("punch", "die", "blank_holder"):
    shutil.copy(source / "prm" / "tools" / "square_cup" / (tool + ".step"),
                project / "tools")
(project / "outline.txt").write_text("-60 -60\n60 -60\n60 60\n-60 60\n")

failures = []


def check(what, ok, detail=""):
    print(("  ok   " if ok else "  FAIL ") + what + (": " + detail if detail else ""))
    if not ok:
        failures.append(what)


def prm(final_load, radial_elements):
    """The coarse square cup on its STEP tools and a polygon outline, the
    files named relative to the prm."""
    tools = "".join(
        "  subsection Tool %d\n    set Geometry = cad\n"
        "    set File = tools/%s.step\n  end\n" % (k + 1, name)
        for k, name in enumerate(("punch", "die", "blank_holder")))
    return ("include %s\n" % (source / "prm" / "square_cup.prm")
            + "subsection Geometry\n  set Blank outline = polygon\n"
            "  set Outline file = outline.txt\n"
            "  set Elements along radius = %d\nend\n" % radial_elements
            + "subsection Process\n  set Final load = %g\nend\n" % final_load
            + "subsection Contact\n" + tools + "end\n"
            "subsection Output\n  set Write VTU = false\nend\n")


def study(name, final_load, values, radial_elements=4):
    (project / (name + ".prm")).write_text(prm(final_load, radial_elements))
    return [args.deepdraw, str(project / (name + ".prm")), "--output-directory",
            str(work / name), "--study",
            "Geometry/Layers through thickness = " + values]


def rows(output):
    with open(output / "study.csv", newline="") as f:
        return list(csv.DictReader(f))


# Relative paths, the study started in another directory.
run = subprocess.run(study("paths", 0.3, "1, 2"), cwd=work,
                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                     timeout=900)
check("paths: exit code 0", run.returncode == 0,
      "%d: %s" % (run.returncode, run.stderr.strip()[-300:]))
if (work / "paths" / "study.csv").exists():
    found = rows(work / "paths")
    check("paths: two rows ok", [r["status"] for r in found] == ["ok", "ok"],
          str([(r["status"], r["note"]) for r in found]))
    text = (work / "paths" / "run_1_1" / "input.prm").read_text()
    for entry, path in (("Outline file", project / "outline.txt"),
                        ("File", project / "tools" / "punch.step")):
        check("paths: input.prm sets %s = %s" % (entry, path),
              "set %s = %s\n" % (entry, path) in text)


def interrupted(name, whole_group):
    """Starts a study of two long runs (some seconds each) and sends SIGINT
    during the first, once it has reported an increment."""
    command = study(name, 30, "1, 2", radial_elements=10)
    process = subprocess.Popen(command, cwd=work, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True,
                               start_new_session=True)
    log = work / name / "run_1_1" / "deepdraw.log"
    deadline = time.time() + 300
    # Until the first run reports its first increment.
    while time.time() < deadline and process.poll() is None:
        if log.exists() and "increment " in log.read_text():
            break
        time.sleep(0.2)
    if whole_group:
        os.killpg(process.pid, signal.SIGINT)
    else:
        process.send_signal(signal.SIGINT)
    out, err = process.communicate(timeout=300)
    check(name + ": exit code 130", process.returncode == 130,
          "%d: %s" % (process.returncode, err.strip()[-300:]))
    check(name + ": message names SIGINT and the rows",
          "stopped by SIGINT after 1 of 2 runs" in err, err.strip()[-300:])
    found = rows(work / name) if (work / name / "study.csv").exists() else []
    check(name + ": one row, interrupted",
          [r["status"] for r in found] == ["interrupted"],
          str([(r["status"], r["note"]) for r in found]))
    check(name + ": the run stopped with its checkpoint",
          (work / name / "run_1_1" / "checkpoint.bin").exists())
    check(name + ": no second run", not (work / name / "run_2_2").exists())


interrupted("ctrl_c", True)
interrupted("sigint_to_the_study", False)
if failures:
    sys.exit("FAILED: %d check(s): %s" % (len(failures), "; ".join(failures)))
print("all checks passed")
