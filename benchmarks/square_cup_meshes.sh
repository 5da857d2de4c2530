#!/bin/sh
# Mesh series of the square cup (not a test, doc/results.md § Speed): runs
# prm/square_cup.prm with only the mesh changed (N x N x 2 hexahedra) to a
# punch travel, one mesh after the other, and prints per mesh the wall time
# of the process, increments, Newton iterations, the time split from
# statistics.csv (assembly, contact, linear solve, output) and the
# unknowns (all, and the rows of the factorised matrix at the first and the
# last increment, D60), the factorisations and the solves with kept factors
# (their GMRES iterations, D185) from the run's summary, and the peak
# resident memory (with /usr/bin/time, Debian's package time); then the
# exponents p of wall = c cells^p and memory = c cells^p fitted by least
# squares in log-log, and a plot of wall time against cells.
#
#   benchmarks/square_cup_meshes.sh [TRAVEL_MM [N ...]]
# TRAVEL_MM defaults to 8.1, N to "25 50 100 150" (1 250 ... 45 000 cells).
# SOLVER=AMG (or UMFPACK, KLU) in the environment sets Linear solver/Type
# (default MUMPS; doc/results.md § Algebraic multigrid).
# REUSE=true|false|auto sets Linear solver/Reuse factorisation (default
# auto since D206: on for 50 x 50 and finer; false for the figures before).
# PRECISION=double|single|auto sets Linear solver/Factorisation precision
# (default auto since D226: single-precision factors where factorisations
# are reused; double for the figures before).
# DEEPDRAW selects the executable (default build/deepdraw). Outputs and
# wall_time.png go to a fresh temporary directory (printed, kept). The
# figures are wall-clock times: run it on an otherwise idle machine.
set -e
source_dir=$(cd "$(dirname "$0")/.." && pwd)
deepdraw=${DEEPDRAW:-$source_dir/build/deepdraw}
travel=${1:-8.1}
[ $# -gt 0 ] && shift
meshes=${*:-25 50 100 150}
solver=${SOLVER:-MUMPS}
reuse=${REUSE:-auto}
precision=${PRECISION:-auto}
output=$(mktemp -d /tmp/square_cup_meshes.XXXXXX)
[ -x "$deepdraw" ] || { echo "square_cup_meshes.sh: $deepdraw missing" >&2; exit 1; }

for n in $meshes; do
  run="$output/$n"
  mkdir -p "$run"
  cat > "$run/mesh.prm" <<PRM
include $source_dir/prm/square_cup.prm
subsection Geometry
  set Elements along x = $n
  set Elements along y = $n
end
subsection Process
  set Final load = $travel
end
subsection Linear solver
  set Type = $solver
  set Reuse factorisation = $reuse
  set Factorisation precision = $precision
end
PRM
  measure=""
  [ -x /usr/bin/time ] && measure="/usr/bin/time -f %M -o $run/peak_kb"
  start=$(date +%s.%N)
  if ! $measure "$deepdraw" "$run/mesh.prm" --output-directory "$run/out" > "$run/log" 2>&1; then
    tail -3 "$run/log"
    echo "  $n x $n: run failed (log $run/log)"
    continue
  fi
  end=$(date +%s.%N)
  echo "$n $start $end" >> "$output/walls"
done

python3 - "$output" <<'PYTHON'
import csv
import math
import re
import sys

output = sys.argv[1]
points = []
memories = []
print("| mesh | cells | unknowns (u + contact) | factorised rows (first, last increment) "
      "| wall | increments | Newton it. | factorisations | kept-factor solves (GMRES it.) "
      "| assembly | contact | linear solve (per it.) | output | peak memory |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for line in open(output + "/walls"):
    n, start, end = line.split()
    wall = float(end) - float(start)
    rows = list(csv.DictReader(open("%s/%s/out/statistics.csv" % (output, n))))
    total = lambda key: sum(float(r[key]) for r in rows)
    iterations = total("newton_iterations")
    log = open("%s/%s/log" % (output, n)).read()
    match = re.search(r"(\d+) cells, (\d+) displacement unknowns, (\d+) contact", log)
    cells, n_u, n_c = (int(g) for g in match.groups())
    points.append((cells, wall))
    # Printed where a kept factorisation was used (D206); otherwise every
    # Newton iteration factorised.
    kept = re.search(r"(\d+) factorisations, (\d+) solves with a kept "
                     r"factorisation \((\d+) GMRES", log)
    factorised, reused, gmres = (kept.groups() if kept
                                 else (int(iterations), 0, 0))
    try:
        peak = float(open("%s/%s/peak_kb" % (output, n)).read().split()[-1]) / 1e6
        memories.append((cells, peak))
        peak_text = "%.2f GB" % peak
    except (OSError, ValueError, IndexError):
        peak_text = "—"
    print("| %s × %s × 2 | %d | %d + %d | %s, %s | %.1f s | %d | %d | %s | %s (%s) "
          "| %.1f s | %.1f s | %.1f s (%.3f s) | %.1f s | %s |"
          % (n, n, cells, n_u, n_c, rows[0]["factorized_unknowns"],
             rows[-1]["factorized_unknowns"], wall, len(rows), iterations,
             factorised, reused, gmres,
             total("assembly_s"), total("contact_search_s"),
             total("linear_solve_s"), total("linear_solve_s") / iterations,
             total("output_s"), peak_text))


def fit(pairs):
    """c, p of value = c cells^p, least squares in log-log."""
    x = [math.log(a) for a, _ in pairs]
    y = [math.log(b) for _, b in pairs]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    p = sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)
    return math.exp(my - p * mx), p


if len(memories) > 1:
    print("fitted: peak memory = %.3g GB * cells^%.2f" % fit(memories))
if len(points) > 1:
    c, p = fit(points)
    print("fitted: wall = %.3g s * cells^%.2f" % (c, p))
    with open(output + "/wall.dat", "w") as f:
        for cells, wall in points:
            f.write("%d %.2f\n" % (cells, wall))
    with open(output + "/fit.gp", "w") as f:
        f.write("c = %.6g\np = %.6g\n" % (c, p))
PYTHON

if command -v gnuplot > /dev/null && [ -f "$output/wall.dat" ]; then
  gnuplot <<GNUPLOT
load "$output/fit.gp"
set terminal pngcairo size 700,450 font 'Sans,10'
set output "$output/wall_time.png"
set logscale xy
set xlabel "cells (N x N x 2)"
set ylabel "wall time (s), punch 0 -> $travel mm"
set grid
set key top left
plot "$output/wall.dat" using 1:2 with linespoints pt 7 title "deepdraw", \
     c * x**p with lines dt 2 title sprintf("fit: %.3g cells^{%.2f}", c, p)
GNUPLOT
fi
echo "outputs in $output"
