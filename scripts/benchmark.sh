#!/usr/bin/env bash
# Performance summary: builds the benchmark programs (in the existing build/
# directory, or via scripts/setup.sh if there is none), runs
#   bench_problem_assembly     assembly cost per cell of the reference blank
#   bench_material_update      cost of one return mapping (Hill'48, Yld2004-18p)
#   bench_geometry_projection  closest-point projection (if present)
# and a timed run of prm/tension_bar.prm (increments, Newton iterations per
# increment and the time split from statistics.csv), then prints a summary.
#   scripts/benchmark.sh [assembly repetitions]
set -euo pipefail
cd "$(dirname "$0")/.."
repetitions=${1:-40}
jobs=$(nproc)

if [ -d build ]; then
  echo "benchmark: building in the existing build/"
  cmake --build build --target deepdraw bench_problem_assembly bench_material_update -j "$jobs"
  # The geometry benchmark is optional: build it if its target exists.
  if cmake --build build --target help 2>/dev/null | grep -q bench_geometry_projection; then
    cmake --build build --target bench_geometry_projection -j "$jobs" \
      || echo "benchmark: bench_geometry_projection does not build, skipped"
  fi
else
  echo "benchmark: no build/ directory, running scripts/setup.sh"
  scripts/setup.sh
fi

log=$(mktemp -d)
trap 'rm -rf "$log"' EXIT

run_benchmark() {
  local name=$1
  shift
  if [ -x "build/benchmarks/$name" ]; then
    echo
    echo "== $name"
    "build/benchmarks/$name" "$@" | tee "$log/$name.txt"
  else
    echo
    echo "== $name: not built, skipped"
  fi
}
run_benchmark bench_problem_assembly "$repetitions"
run_benchmark bench_material_update
run_benchmark bench_geometry_projection

echo
echo "== prm/tension_bar.prm"
output="$log/tension_bar"
start=$(date +%s.%N)
build/deepdraw prm/tension_bar.prm --output-directory "$output" > "$log/tension_bar.txt"
end=$(date +%s.%N)
tail -n 1 "$log/tension_bar.txt"

python3 - "$output/statistics.csv" "$start" "$end" "$log" <<'EOF'
import csv, os, sys

statistics, start, end, log = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
with open(statistics) as f:
    rows = list(csv.DictReader(f))
total = lambda key: sum(float(r[key]) for r in rows)
increments = len(rows)
iterations = total("newton_iterations")
cut_backs = total("cut_backs")
assembly, solve, output, wall = (total(k) for k in ("assembly_s", "linear_solve_s", "output_s", "wall_s"))
elapsed = end - start
other = max(wall - assembly - solve - output, 0.0)

def line(name, seconds):
    share = 100.0 * seconds / wall if wall > 0 else 0.0
    print("    %-26s %8.3f s  %5.1f %%" % (name, seconds, share))

print()
print("=" * 64)
print("deepdraw benchmark summary")
print("=" * 64)
for name in ("bench_problem_assembly", "bench_material_update", "bench_geometry_projection"):
    path = os.path.join(log, name + ".txt")
    if os.path.exists(path):
        print(name + ":")
        for text in open(path).read().splitlines():
            print("    " + text.strip())
print("tension bar (prm/tension_bar.prm):")
print("    increments                 %8d   (cut-backs %d)" % (increments, cut_backs))
print("    Newton iterations          %8d   (%.2f per increment)"
      % (iterations, iterations / increments if increments else 0.0))
line("assembly", assembly)
line("linear solve", solve)
line("output (VTU, CSV)", output)
line("other (update, set-up)", other)
line("sum of increments", wall)
print("    %-26s %8.3f s  (process, incl. start-up)" % ("wall time", elapsed))
EOF
