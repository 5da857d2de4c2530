"""Checks of press_retract.prm, a release by tool retraction (D150).

The tools move away with contact active; the run ends only if every pair is
open at the stage's end (else exit 3), so at t = 2 neither tool carries a
force (|F| <= 1e-9 N). The released shape must agree with the force
release of press_release.prm, run here with the same executable: the
mid-surface of the section profile at the end of stage 2, point by point,
within 1e-9 mm (both end stress-free, held by the same support; each
converged to a force tolerance of 1e-12, and the CSV keeps 10 digits of
coordinates of order 1 mm; measured: equal to the last digit).
"""
import os
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from script_test import csv_rows as rows  # noqa: E402


def main(output):
    failures = []
    source = pathlib.Path(__file__).resolve().parent
    prm = (source / "press_release.prm").read_text().replace(
        "../contact/data", str(source.parent / "contact" / "data"))
    pathlib.Path("force_release.prm").write_text(prm)
    result = subprocess.run([os.environ["DEEPDRAW"], "force_release.prm",
                             "--output-directory", "force_release"],
                            capture_output=True, text=True)
    if result.returncode != 0:
        print(result.stdout, result.stderr)
        return 1

    tools = {row["load"]: row for row in rows(output + "/tools.csv")}
    for name in ("holder_Fz", "die_Fz"):
        value = tools[2.0][name]
        ok = abs(value) <= 1e-9
        print("retracted: %s = %.3g N%s" % (name, value, "" if ok else
                                             "  FAILED"))
        if not ok:
            failures.append(name)
    retracted = rows(output + "/section_profile_stage2.csv")
    released = rows("force_release/section_profile_stage2.csv")
    largest = max(abs(a[c] - b[c]) for a, b in zip(retracted, released)
                  for c in ("x", "y", "z"))
    print("released shape: tool retraction against force release, largest "
          "difference %.3g mm over %d points" % (largest, len(retracted)))
    if len(retracted) != len(released) or largest > 1e-9:
        failures.append("the two releases give different shapes")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
