"""Checks the study of square_cup_study.prm: per row, the punch force, DX,
DY, DD at 0.5 and 1 mm and the smallest thickness strain on OX and OD with
its s0 equal what the run's own CSV files hold (read here independently);
cells and unknowns of a 12 x 12 x layers mesh; the row of 2 layers equals a
direct run of the same prm (started here with $DEEPDRAW): the same values
and the same process-table files byte for byte."""
import filecmp
import os
import pathlib
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, str(pathlib.Path(__file__).parent))
from study_common import check, close, cost, finish, number, read_study, run_values

output = pathlib.Path(sys.argv[1])
rows = read_study(output)
check("two rows", len(rows) == 2, "%d rows" % len(rows))
travels = (0.5, 1.0)
check("travel columns 0.5 and 1 mm only (30 mm is beyond the final load)",
      [c for c in rows[0] if c.startswith("punch_force_N")] ==
      ["punch_force_N_0.5mm", "punch_force_N_1mm"])

for row, layers in zip(rows, (1, 2)):
    run = "%d layer(s): " % layers
    folder = output / ("run_%d_%d" % (layers, layers))
    check(run + "status ok", row["status"] == "ok", row["status"] + " " + row["note"])
    check(run + "value", row["Geometry/Layers through thickness"] == str(layers))
    close(run + "cells", number(row, "cells"), 12 * 12 * layers)
    close(run + "unknowns", number(row, "displacement_unknowns"),
          3 * 13 * 13 * (layers + 1))
    check(run + "contact unknowns", number(row, "contact_unknowns") > 0)
    close(run + "aspect ratio", number(row, "aspect_ratio"),
          (75 / 12) / (0.81 / layers))
    n, iterations, cut_backs = cost(folder)
    close(run + "increments", number(row, "increments"), n)
    close(run + "iterations", number(row, "newton_iterations"), iterations)
    for travel in travels:
        for column, value in run_values(folder, travel).items():
            close(run + column + " from the run's files", number(row, column), value)
    check(run + ("one-layer remark" if layers == 1 else "no remark"),
          ("below the reference model's validity" in row["note"]) == (layers == 1),
          row["note"])

# The same prm run directly.
prm = pathlib.Path(__file__).with_name("square_cup_study.prm")
direct = pathlib.Path("direct")
run = subprocess.run([os.environ["DEEPDRAW"], str(prm), "--output-directory",
                      str(direct)], stdout=subprocess.DEVNULL)
check("direct run done", run.returncode == 0)
for travel in travels:
    for column, value in run_values(direct, travel).items():
        close("2 layers: " + column + " equals the direct run",
              number(rows[1], column), value, rel=0.0)
for name in ("punch_force.csv", "draw_in.csv", "thickness_OX_1mm.csv",
             "thickness_OD_1mm.csv", "statistics.csv"):
    same = filecmp.cmp(direct / name, output / "run_2_2" / name, shallow=False)
    if name == "statistics.csv":
        # Times differ; the other columns must not.
        import csv
        def untimed(path):
            with open(path) as f:
                return [{k: v for k, v in r.items() if not k.endswith("_s")}
                        for r in csv.DictReader(f)]
        same = untimed(direct / name) == untimed(output / "run_2_2" / name)
    check(name + " of the study's run equals the direct run's", same)
finish()
