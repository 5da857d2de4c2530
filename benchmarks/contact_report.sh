#!/bin/sh
# Contact benchmark (not a test): runs the Hertz cylinder (issue 4, test 4)
# and the ironing case (test 5) and reports, from statistics.csv, the Newton
# iterations per increment and the split of the time into assembly, contact
# search and linear solve. Figures are recorded in doc/results_contact.md.
#
#   benchmarks/contact_report.sh [DEEPDRAW] [OUTPUT_DIR]
# DEEPDRAW defaults to build/deepdraw, OUTPUT_DIR to a fresh temporary
# directory (kept, printed at the end).
set -e
source_dir=$(cd "$(dirname "$0")/.." && pwd)
deepdraw=${1:-$source_dir/build/deepdraw}
output=${2:-$(mktemp -d /tmp/contact_report.XXXXXX)}
mkdir -p "$output"

run_case() {
  name=$1
  prm=$2
  echo "=== $name: $prm"
  "$deepdraw" "$prm" --output-directory "$output/$name" > "$output/$name.log"
  python3 - "$output/$name" <<'PYTHON'
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1] + "/statistics.csv")))
iterations = [int(float(r["newton_iterations"])) for r in rows]
total = lambda key: sum(float(r[key]) for r in rows)
wall = total("wall_s")
print("increments %d, cut-backs %d, Newton iterations per increment:"
      % (len(rows), total("cut_backs")))
print("  " + " ".join(str(i) for i in iterations))
print("  mean %.2f, max %d, total %d" % (sum(iterations) / len(rows),
                                          max(iterations), sum(iterations)))
print("time (s): wall %.3f = assembly %.3f (%.0f %%) + contact %.3f"
      " (%.0f %%) + linear solve %.3f (%.0f %%) + output %.3f + other %.3f"
      % (wall, total("assembly_s"), 100 * total("assembly_s") / wall,
         total("contact_search_s"), 100 * total("contact_search_s") / wall,
         total("linear_solve_s"), 100 * total("linear_solve_s") / wall,
         total("output_s"),
         wall - total("assembly_s") - total("contact_search_s")
         - total("linear_solve_s") - total("output_s")))
print("per Newton iteration (s): assembly %.4f, contact %.5f, linear"
      " solve %.4f" % (total("assembly_s") / sum(iterations),
                       total("contact_search_s") / sum(iterations),
                       total("linear_solve_s") / sum(iterations)))
PYTHON
  grep "^deepdraw:" "$output/$name.log" | head -1
}

run_case hertz_cylinder "$source_dir/tests/contact/data/hertz_cylinder.prm"
run_case ironing_split_tool "$source_dir/tests/contact/ironing_split_tool.prm"
echo "results in $output"
