#!/usr/bin/env python3
"""Resuming a force release (D150): the run of press_release.prm writes a
checkpoint at the end of stage 1, which holds the forces the release takes
over as loads. A copy of its output directory, resumed with --resume,
begins the release from that checkpoint and must repeat the uninterrupted
run bit for bit: every CSV table (but for the wall-time columns *_s and the
orderings counted in statistics.csv, as the other restart tests; the
section profiles at the end of each stage among them) and the
last VTU file, the released shape, byte for byte.

    release_resume_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402


def vtu_data(path):
    """A VTU file without deal.II's comment, which holds the time of day."""
    text = path.read_bytes()
    start, end = text.find(b"<!--"), text.find(b"-->")
    return text[:start] + text[end + 3:] if start >= 0 and end > start \
        else text


def main():
    args, source, work = script_test.start(__doc__)
    text = script_test.write_case(source, work,
                                  "tests/springback/press_release.prm")
    (work / "case" / "process.prm").write_text(text.replace(
        "set Write VTU = false", "set Write VTU = true\n"
        "  set VTU fields = displacement, springback displacement, stress")
        .replace("List of postprocessors = ",
                 "List of postprocessors = visualization, "))
    failures = script_test.run_and_resume(args.deepdraw, work, 1)
    last = sorted(p.name for p in (work / "full").glob("solution-*.vtu"))[-1]
    same = vtu_data(work / "full" / last) == vtu_data(work / "resumed" / last)
    print("%s %s" % ("same" if same else "DIFFERENT", last))
    if not same:
        failures.append(last + " (the released shape) differs")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
