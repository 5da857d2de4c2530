#!/bin/sh
# Square-cup benchmark (issue 5, not a test): runs prm/square_cup.prm from
# the Release build to a given punch travel with each requested direct
# solver and prints wall time, increments, Newton iterations per increment,
# cut-backs and the time split (assembly, contact, linear solve,
# output) from statistics.csv, whose times include failed attempts.
#
#   benchmarks/square_cup.sh [TRAVEL_MM [SOLVER ...]]
# TRAVEL_MM defaults to 15 (the issue's target: 0 -> 15 mm in <= 30 s,
# <= 5 Newton iterations per increment), SOLVER to "UMFPACK MUMPS KLU".
# Outputs go to a fresh temporary directory (printed, kept). Run it on an
# otherwise idle machine: the figures are wall-clock times.
set -e
source_dir=$(cd "$(dirname "$0")/.." && pwd)
deepdraw=${DEEPDRAW:-$source_dir/build/deepdraw}
travel=${1:-15}
[ $# -gt 0 ] && shift
solvers=${*:-UMFPACK MUMPS KLU}
output=$(mktemp -d /tmp/square_cup_benchmark.XXXXXX)
[ -x "$deepdraw" ] || { echo "square_cup.sh: $deepdraw missing; run scripts/setup.sh" >&2; exit 1; }

for solver in $solvers; do
  run="$output/$solver"
  mkdir -p "$run"
  # The prm includes the reference case and overrides travel and solver only.
  cat > "$run/benchmark.prm" <<PRM
include $source_dir/prm/square_cup.prm
subsection Process
  set Final load = $travel
end
subsection Linear solver
  set Type = $solver
end
PRM
  echo "=== square cup 0 -> $travel mm, $solver"
  start=$(date +%s.%N)
  if ! "$deepdraw" "$run/benchmark.prm" --output-directory "$run/out" > "$run/log" 2>&1; then
    tail -3 "$run/log"
    echo "  $solver: run failed (log $run/log)"
    continue
  fi
  end=$(date +%s.%N)
  python3 - "$run/out" "$start" "$end" <<'PYTHON'
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1] + "/statistics.csv")))
wall = float(sys.argv[3]) - float(sys.argv[2])
iterations = sum(int(float(r["newton_iterations"])) for r in rows)
total = lambda key: sum(float(r[key]) for r in rows)
print("wall %.1f s (process), increments %d, cut-backs %d, Newton iterations"
      " %d (%.2f per increment, converged attempts)"
      % (wall, len(rows), total("cut_backs"), iterations,
         iterations / len(rows)))
parts = [("assembly", "assembly_s"), ("contact", "contact_search_s"),
         ("linear solve", "linear_solve_s"), ("output", "output_s")]
increments = total("wall_s")
line = ", ".join("%s %.1f s (%.0f %%)" % (name, total(key),
                                         100 * total(key) / increments)
                 for name, key in parts)
print("time in increments %.1f s: %s" % (increments, line))
PYTHON
done
echo "outputs in $output"
