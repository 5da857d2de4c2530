"""Checks the study of tension_bar_study.prm (runs listed there): every row
present in the order of the values, the varied values, cells and
displacement unknowns equal to the counts of an nx x ny x layers brick mesh,
the aspect ratio, the cost equal to the run's own statistics.csv, the
failed rows marked with the run's reason, the one-layer remark, the run
folders and their input.prm, and study.png."""
import pathlib
import shutil
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, str(pathlib.Path(__file__).parent))
from study_common import check, close, finish, number, read_study, cost

output = pathlib.Path(sys.argv[1])
rows = read_study(output)
# (elements along x, layers, max iterations, expected status); the bar is
# 10 x 1 x 1 mm with 2 elements along y.
expected = [(2, 1, 15, "ok"), (3, 0, 15, "failed"), (4, 2, 15, "ok"),
            (2, 2, 1, "failed")]
check("one row per run", len(rows) == len(expected), "%d rows" % len(rows))
check("no travel columns (final load 1 < 15 mm)",
      not any(c.endswith("mm") and c.startswith("punch") for c in rows[0]))

folders = sorted(p for p in output.iterdir() if p.is_dir())
check("one folder per run", [p.name for p in folders] ==
      ["run_1_2_1_15", "run_2_3_0_15", "run_3_4_2_15", "run_4_2_2_1"],
      str([p.name for p in folders]))

for k, (row, (nx, layers, iterations, status)) in enumerate(zip(rows, expected)):
    run = "run %d: " % (k + 1)
    check(run + "values", (row["Geometry/Elements along x"],
                           row["Geometry/Layers through thickness"],
                           row["Newton/Maximum iterations"]) ==
          (str(nx), str(layers), str(iterations)))
    check(run + "status " + status, row["status"] == status, row["status"])
    text = (folders[k] / "input.prm").read_text()
    check(run + "input.prm includes the prm and sets the values",
          "include " + str(pathlib.Path(__file__).with_name("tension_bar_study.prm"))
          in text and "set Layers through thickness = %d" % layers in text)
    check(run + "wall time measured", number(row, "wall_s") > 0)
    if layers == 0:
        # Rejected by the run's input check: nothing computed.
        check(run + "reason is the run's input error",
              "Layers through thickness" in row["note"] and
              "does not match" in row["note"], row["note"])
        check(run + "no mesh", row["cells"] == "" and row["increments"] == "")
        continue
    ny = 2
    close(run + "cells = nx ny layers", number(row, "cells"), nx * ny * layers)
    close(run + "unknowns = 3 (nx+1)(ny+1)(layers+1)",
          number(row, "displacement_unknowns"),
          3 * (nx + 1) * (ny + 1) * (layers + 1))
    close(run + "no contact unknowns", number(row, "contact_unknowns"), 0)
    close(run + "aspect ratio", number(row, "aspect_ratio"),
          max(10 / nx, 1 / ny) / (1 / layers))
    increments, iterations_done, cut_backs = cost(folders[k])
    close(run + "increments", number(row, "increments"), increments)
    close(run + "Newton iterations", number(row, "newton_iterations"), iterations_done)
    close(run + "cut-backs", number(row, "cut_backs"), cut_backs)
    if status == "ok":
        check(run + "at least 20 increments to t = 1", increments >= 20)
    else:
        check(run + "reason is the run's own last line",
              row["note"].startswith("deepdraw: the run stopped:"), row["note"])
    one_layer = "below the reference model's validity (at least two layers)"
    check(run + ("one-layer remark" if layers == 1 else "no one-layer remark"),
          (one_layer in row["note"]) == (layers == 1), row["note"])

if shutil.which("gnuplot"):
    png = output / "study.png"
    check("study.png is a PNG", png.exists() and
          png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n")
check("study.gp written", (output / "study.gp").exists())
finish()
