#!/usr/bin/env bash
# Renders the sheet and the tools of a deepdraw run at one punch travel into a
# PNG (see render_square_cup.py):
#   scripts/render_square_cup.sh OUTPUT_DIR PNG_FILE [TRAVEL [FIELD [WIDTH]]]
# Needs pvpython (Debian: python3-paraview) and, without a display, Xvfb
# (Debian: xvfb): Debian's ParaView renders through X only (no EGL/OSMesa),
# so --force-offscreen-rendering alone aborts with "bad X server connection".
set -euo pipefail

if [ $# -lt 2 ] || [ $# -gt 5 ]; then
  echo "usage: $0 OUTPUT_DIR PNG_FILE [TRAVEL [FIELD [WIDTH]]]" >&2
  exit 2
fi
script="$(dirname "$0")/render_square_cup.py"
pvpython=$(command -v pvpython || true)
if [ -z "$pvpython" ]; then
  echo "render: pvpython not found; install ParaView's Python (Debian: apt-get install python3-paraview)" >&2
  exit 1
fi

command=("$pvpython" --force-offscreen-rendering "$script" "$@")
if [ -z "${DISPLAY:-}" ]; then
  if command -v xvfb-run > /dev/null; then
    # -noreset: Xvfb resets when its last client disconnects, and a window
    # ParaView opens during that reset fails ("bad X server connection",
    # about every second run without it).
    command=(xvfb-run -a -s "-screen 0 1920x1200x24 -noreset" "${command[@]}")
  else
    echo "render: no DISPLAY and no xvfb-run; trying without (install xvfb if pvpython aborts on the X connection)" >&2
  fi
fi
exec "${command[@]}"
