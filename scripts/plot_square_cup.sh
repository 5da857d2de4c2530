#!/usr/bin/env bash
# PNG plots of the square-cup CSV tables (doc/user_guide.md §3, doc/results.md), without a display:
#   punch_force.png   punch and blank-holder force vs punch travel
#   draw_in.png       flange draw-in DX, DY, DD vs punch travel
#   thickness_OX.png  thickness strain along OX, one curve per travel file
#   thickness_OD.png  the same along the diagonal OD
# Forces and draw-in have one row per increment (hundreds): lines only.
# A plot whose CSV files are missing (or hold no data row) is skipped with a
# message, so the script also works on a run that stopped early.
#   scripts/plot_square_cup.sh OUTPUT_DIR [FIGURE_DIR]   (default doc/figures)
# Needs gnuplot (Debian: gnuplot-nox).
set -euo pipefail

if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: $0 OUTPUT_DIR [FIGURE_DIR]" >&2
  exit 2
fi
out=$1
fig=${2:-doc/figures}
command -v gnuplot > /dev/null || { echo "plot: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
[ -d "$out" ] || { echo "plot: no directory $out" >&2; exit 1; }
mkdir -p "$fig"

# pngcairo gives anti-aliased lines; the libgd png terminal is the fallback.
if gnuplot -e 'set terminal' 2>&1 | grep -qw pngcairo; then
  terminal="pngcairo enhanced size 900,500 font 'Sans,11'"
else
  terminal="png size 900,500"
fi
preamble="set terminal $terminal
set datafile separator ','
set grid
# Legend right of the plot: inside it hides some curve, below it collides
# with the x label once it wraps.
set key outside right top vertical box"

# True if the file exists and has at least one row below the header
# (gnuplot stops with an error on a plot without any point).
has_data() { [ -f "$1" ] && [ "$(wc -l < "$1")" -ge 2 ]; }

status=0
plot() { # plot NAME GNUPLOT_COMMANDS: write FIGURE_DIR/NAME.png, keep going on error
  # Fed on stdin: gnuplot -e does not accept multi-line commands.
  if gnuplot <<< "$preamble
set output '$fig/$1.png'
$2"; then
    echo "plot: wrote $fig/$1.png"
  else
    echo "plot: gnuplot failed on $1.png" >&2
    status=1
  fi
}

file="$out/punch_force.csv"
if has_data "$file"; then
  plot punch_force "set title 'Square cup: tool forces (quarter model)'
set xlabel 'punch travel (mm)'
set ylabel 'force on the quarter (kN)'
plot '$file' skip 1 using 1:(\$2/1000) with lines lw 2 title 'punch force', \
     '' skip 1 using 1:(\$3/1000) with lines lw 2 dt 2 title 'holder force'"
else
  echo "plot: $file missing or empty, punch_force.png skipped"
fi

file="$out/draw_in.csv"
if has_data "$file"; then
  plot draw_in "set title 'Square cup: draw-in of the flange edge'
set xlabel 'punch travel (mm)'
set ylabel 'draw-in (mm)'
plot '$file' skip 1 using 1:2 with lines lw 2 title 'DX (x midside)', \
     '' skip 1 using 1:3 with lines lw 2 dt 2 title 'DY (y midside)', \
     '' skip 1 using 1:4 with lines lw 2 title 'DD (diagonal)'"
else
  echo "plot: $file missing or empty, draw_in.png skipped"
fi

for axis in OX OD; do
  # One curve per travel, in increasing travel (15 before 7.5 in a plain glob).
  files=()
  while IFS= read -r f; do
    has_data "$f" && files+=("$f")
  done < <(find "$out" -maxdepth 1 -name "thickness_${axis}_*mm.csv" \
             | sed -E "s/.*thickness_${axis}_(.*)mm\.csv$/\1 &/" | sort -g | cut -d' ' -f2-)
  if [ ${#files[@]} -eq 0 ]; then
    echo "plot: no $out/thickness_${axis}_<travel>mm.csv with data, thickness_${axis}.png skipped"
    continue
  fi
  curves=""
  for f in "${files[@]}"; do
    travel=$(basename "$f" | sed -E "s/thickness_${axis}_(.*)mm\.csv/\1/")
    curves+="${curves:+, }'$f' skip 1 using 1:2 with linespoints pt 7 ps 0.5 lw 2 title '$travel mm'"
  done
  [ "$axis" = OX ] && along="along OX (y = 0)" || along="along the diagonal OD"
  plot "thickness_$axis" "set title 'Square cup: thickness strain $along'
set xlabel 'initial distance from the cup centre s_0 (mm)'
set ylabel 'thickness strain ln(t/t_0)'
set key title 'punch travel' width 2
plot $curves"
done

exit $status
