#!/bin/sh
# Strong scaling of MPI runs (not a test, doc/results.md § Parallel runs,
# D199): the square cup of prm/square_cup.prm on N x N x 2 cells to a punch
# travel, under `mpirun -np R` for each rank count R, and per run the wall
# time of the job, increments, Newton iterations, the time split from
# statistics.csv (assembly, contact, linear solve: rank 0's clock),
# the largest resident memory of a rank, and the speed-up and parallel
# efficiency against the run on the fewest ranks of the same mesh.
#
#   benchmarks/parallel_scaling.sh [TRAVEL_MM [N ...]]
# TRAVEL_MM defaults to 8.1, N to "100 200" (20 000 and 80 000 cells).
# RANKS sets the rank counts (default "1 2 4 8 16"); MPIRUN the launcher and
# its options (default "mpirun --oversubscribe"; as root, set
# OMPI_ALLOW_RUN_AS_ROOT=1 and OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1). The memory
# column needs GNU time (/usr/bin/time, Debian package time); without it
# the column says "-". DEEPDRAW selects the executable (default
# build/deepdraw). Outputs go to a fresh temporary directory (printed,
# kept). Wall-clock figures: run it on an otherwise idle machine, with no
# more ranks than cores.
set -e
source_dir=$(cd "$(dirname "$0")/.." && pwd)
deepdraw=${DEEPDRAW:-$source_dir/build/deepdraw}
travel=${1:-8.1}
[ $# -gt 0 ] && shift
meshes=${*:-100 200}
ranks_list=${RANKS:-1 2 4 8 16}
mpirun=${MPIRUN:-mpirun --oversubscribe}
output=$(mktemp -d /tmp/parallel_scaling.XXXXXX)
[ -x "$deepdraw" ] || { echo "parallel_scaling.sh: $deepdraw missing" >&2; exit 1; }
timer=""
[ -x /usr/bin/time ] && timer="/usr/bin/time -f peak_kB=%M"

for n in $meshes; do
  mkdir -p "$output/$n"
  cat > "$output/$n/mesh.prm" <<PRM
include $source_dir/prm/square_cup.prm
subsection Geometry
  set Elements along x = $n
  set Elements along y = $n
end
subsection Process
  set Final load = $travel
end
subsection Output
  set Output interval = 1000
end
PRM
  for r in $ranks_list; do
    run="$output/$n/ranks_$r"
    start=$(date +%s.%N)
    # shellcheck disable=SC2086
    if ! $mpirun -np "$r" $timer "$deepdraw" "$output/$n/mesh.prm" \
         --output-directory "$run" --quiet > "$run.log" 2>&1; then
      tail -3 "$run.log"
      echo "  $n x $n on $r ranks: run failed (log $run.log)"
      continue
    fi
    end=$(date +%s.%N)
    echo "$n $r $start $end" >> "$output/walls"
  done
done

python3 - "$output" <<'PYTHON'
import csv
import re
import sys

output = sys.argv[1]
runs = [line.split() for line in open(output + "/walls")]
print("cells    ranks  wall_s  speed-up  efficiency  increments  newton  "
      "assembly_s  contact_s  linear_solve_s  peak_rank_MB")
first = {}
for n, r, start, end in runs:
    wall = float(end) - float(start)
    rows = list(csv.DictReader(open(f"{output}/{n}/ranks_{r}/statistics.csv")))
    total = lambda key: sum(float(row[key]) for row in rows)
    peaks = [int(k) for k in re.findall(r"peak_kB=(\d+)",
                                        open(f"{output}/{n}/ranks_{r}.log")
                                        .read())]
    peak = "%.0f" % (max(peaks) / 1024) if peaks else "-"
    base = first.setdefault(n, (int(r), wall))
    speed_up = base[1] / wall
    efficiency = speed_up * base[0] / int(r)
    print("%-8d %5s %7.1f %9.2f %11.2f %11d %7d %11.1f %10.1f %15.1f %13s"
          % (int(n) ** 2 * 2, r, wall, speed_up, efficiency, len(rows),
             total("newton_iterations"), total("assembly_s"),
             total("contact_search_s"), total("linear_solve_s"), peak))
print("outputs in", output)
PYTHON
