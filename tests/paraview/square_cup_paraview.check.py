#!/usr/bin/env python3
"""ParaView reads what deepdraw wrote (doc/user_guide.md §3): runs
read_solution.py with pvpython on the output directory (every VTU part of
solution.pvd opened, the expected point fields present with finite values in
plausible ranges), then renders the thickness strain with the tools to a PNG
with scripts/render_square_cup.py. Fails if pvpython is missing
(python3-paraview, installed by scripts/setup.sh), cannot read a file, or
the picture is not written.

  square_cup_paraview.check.py OUTPUT_DIR
"""
import os
import pathlib
import random
import shutil
import subprocess
import sys

here = pathlib.Path(__file__).resolve().parent
root = here.parent.parent
output = pathlib.Path(sys.argv[1]).resolve()

pvpython = shutil.which("pvpython")
if not pvpython:
    sys.exit("FAILED: pvpython not found; install python3-paraview "
             "(scripts/setup.sh installs it)")
png = output / "thickness_strain.png"
steps = ('"$0" --force-offscreen-rendering "$1" "$2" && '
         '"$0" --force-offscreen-rendering "$3" "$2" "$4"')
command = ["bash", "-c", steps, pvpython, str(here / "read_solution.py"),
           str(output), str(root / "scripts" / "render_square_cup.py"),
           str(png)]
for attempt in range(3):
    run_command = command
    if not os.environ.get("DISPLAY"):
        # Debian's ParaView renders through X only (doc/figures_howto.md):
        # one virtual X server for both steps, at a random display number,
        # since a concurrent xvfb-run -a may take the same one, and without
        # resets: Xvfb resets when its last client leaves, and ParaView's
        # window opened during a reset fails ("bad X server connection").
        # A server that fails anyway is retried.
        if not shutil.which("xvfb-run"):
            sys.exit("FAILED: no DISPLAY and no xvfb-run; install xvfb")
        run_command = ["xvfb-run", "-a", "-n", str(random.randint(100, 30000)),
                       "-s", "-screen 0 1920x1200x24 -noreset"] + command
    run = subprocess.run(run_command, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, timeout=600)
    print(run.stdout)
    if run.returncode == 0 or "FAILED:" in run.stdout:
        break
    print("(attempt %d failed with exit code %d)" % (attempt + 1,
                                                     run.returncode))
if run.returncode != 0:
    sys.exit("FAILED: pvpython exited with %d" % run.returncode)
if not png.is_file() or png.stat().st_size < 20000:
    sys.exit("FAILED: no picture of the thickness strain (%s)" % png)
print("PASSED: ParaView read %s and rendered %s (%d bytes)"
      % (output / "solution.pvd", png.name, png.stat().st_size))
