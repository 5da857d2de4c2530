#!/usr/bin/env python3
"""Checkpoint and restart (doc/user_guide.md §6): a run killed with SIGKILL
at several increments and resumed, and a run stopped with SIGTERM and
resumed, give the same CSV tables and VTU files as the uninterrupted run;
a checkpoint of another model is refused.

Expectation: the resumed run repeats the same arithmetic from the restored
state, so every CSV value and every VTU byte must be identical (D55), apart
from the columns that are wall times (statistics.csv *_s), the count of
orderings computed (statistics.csv symbolic_analyses: MUMPS keeps its
analysis from one increment to the next, a resumed process computes it
anew at its first increment, D97) and the date line deal.II writes into
each VTU file. The tolerance is therefore zero.
"""
import csv
import os
import pathlib
import signal
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402  (tests/script_test.py)

PRM = pathlib.Path(__file__).with_name("short_cup.prm")


def start(deepdraw, work, output, *extra):
    return subprocess.Popen([deepdraw, str(PRM), "--output-directory",
                             str(output), *extra], cwd=work,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)


def run_to_end(deepdraw, work, output, *extra):
    process = start(deepdraw, work, output, *extra)
    out, err = process.communicate(timeout=300)
    if process.returncode != 0:
        sys.exit(f"FAILED: {' '.join(extra)} exit {process.returncode}:\n"
                 f"{out}\n{err}")
    return out


def read_csv(path, skip_times):
    with open(path) as f:
        table = list(csv.reader(f))
    header = table[0]
    keep = [i for i, name in enumerate(header)
            if not (skip_times and (name.endswith("_s")
                                    or name == "symbolic_analyses"))]
    return [[row[i] for i in keep] for row in table]


def vtu_without_date(path):
    lines = path.read_bytes().split(b"\n")
    return b"\n".join(l for l in lines
                      if not l.startswith(b"#This file was generated"))


def compare(reference, resumed, label):
    failures = []
    names = sorted(p.name for p in reference.iterdir()
                   if p.suffix in (".csv", ".vtu", ".pvd"))
    for name in names:
        a, b = reference / name, resumed / name
        if not b.exists():
            failures.append(f"{name} missing")
        elif a.suffix == ".csv":
            skip = name in ("statistics.csv", "adaptivity.csv")
            if read_csv(a, skip) != read_csv(b, skip):
                failures.append(f"{name} differs")
        elif vtu_without_date(a) != vtu_without_date(b):
            failures.append(f"{name} differs")
    extra = sorted(p.name for p in resumed.iterdir()
                   if p.suffix in (".csv", ".vtu") and
                   not (reference / p.name).exists())
    failures += [f"{name} not in the uninterrupted run" for name in extra]
    print(f"{label}: {len(names)} files compared, "
          f"{len(failures)} differences")
    return failures


def main():
    args, _, work = script_test.start(__doc__)
    failures = []

    reference = work / "uninterrupted"
    run_to_end(args.deepdraw, work, reference)

    # SIGKILL at increments 3 and 9 (the second kill hits the resumed run),
    # each resumed from the last checkpoint.
    killed = work / "killed"
    process = start(args.deepdraw, work, killed)
    script_test.stop_after(process, killed, 3, signal.SIGKILL)
    process = start(args.deepdraw, work, killed, "--resume")
    script_test.stop_after(process, killed, 9, signal.SIGKILL)
    out = run_to_end(args.deepdraw, work, killed, "--resume")
    if "resumed at load" not in out:
        failures.append("the resumed run does not say where it resumed")
    failures += compare(reference, killed, "SIGKILL at 3 and 9, resumed")

    # SIGTERM: a checkpoint, a message, exit code 3; then resumed.
    stopped = work / "stopped"
    process = start(args.deepdraw, work, stopped)
    code, out, err = script_test.stop_after(process, stopped, 5, signal.SIGTERM)
    print(err.strip())
    if code != 3:
        failures.append(f"SIGTERM gave exit code {code}, not 3")
    if "stopped by SIGTERM" not in err or "--resume" not in err:
        failures.append("SIGTERM: the message does not say so")
    if not (stopped / "checkpoint.bin").exists():
        failures.append("SIGTERM: no checkpoint written")
    run_to_end(args.deepdraw, work, stopped, "--resume")
    failures += compare(reference, stopped, "SIGTERM, resumed")

    # Another model: refused with the list of changes, nothing changed.
    other = work / "other_model.prm"
    other.write_text(f"include {PRM}\nsubsection Contact\n"
                     "  set Friction coefficient = 0.2\nend\n"
                     "subsection Geometry\n  set Thickness = 0.8\nend\n")
    before = {p.name: p.stat().st_size for p in stopped.iterdir()}
    run = subprocess.run([args.deepdraw, str(other), "--output-directory",
                          str(stopped), "--resume"], cwd=work,
                         capture_output=True, text=True)
    print(run.stderr.strip())
    if run.returncode != 2:
        failures.append(f"another model: exit code {run.returncode}, not 2")
    for change in ("Contact/Friction coefficient: 0.162 -> 0.2",
                   "Geometry/Thickness: 0.81 -> 0.8"):
        if change not in run.stderr:
            failures.append(f"another model: '{change}' not reported")
    after = {p.name: p.stat().st_size for p in stopped.iterdir()}
    if before != after:
        failures.append("another model: the output directory was changed")

    # An output directory without a checkpoint.
    run = subprocess.run([args.deepdraw, str(PRM), "--output-directory",
                          str(work / "never_run"), "--resume"], cwd=work,
                         capture_output=True, text=True)
    if run.returncode != 2 or "no checkpoint" not in run.stderr:
        failures.append("--resume without a checkpoint: "
                        f"exit {run.returncode}: {run.stderr.strip()}")
    if (work / "never_run").exists():
        failures.append("--resume without a checkpoint created its directory")

    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
