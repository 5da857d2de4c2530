#!/usr/bin/env bash
# Writes doc/parameters.md from `deepdraw --print-parameters`: one table per
# subsection (parameter, default, description). Run it after adding or
# changing a parameter (and rebuilding); ctest input/parameter_doc_current
# fails while doc/parameters.md is out of date.
#
#   scripts/generate_parameter_doc.sh [DEEPDRAW [OUTPUT]]
#     DEEPDRAW  the executable (default: build/deepdraw)
#     OUTPUT    the file to write (default: doc/parameters.md; - = stdout)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
deepdraw="${1:-$root/build/deepdraw}"
output="${2:-$root/doc/parameters.md}"

if [ ! -x "$deepdraw" ]; then
  echo "generate_parameter_doc: no executable '$deepdraw'; build first" \
       "(scripts/setup.sh, or cmake --build build --target deepdraw)" >&2
  exit 1
fi

listing="$(mktemp)"
trap 'rm -f "$listing" "$listing.md"' EXIT
"$deepdraw" --print-parameters > "$listing"

# The listing is deal.II's PRM format: 'subsection NAME' ... 'end' (nested),
# '# text' lines documenting the next entry, 'set NAME = VALUE'. Any other
# line is an error, so that nothing is dropped silently.
python3 - "$listing" > "$listing.md" <<'EOF'
import sys

lines = open(sys.argv[1]).read().splitlines()
path, comment, sections, order = [], [], {}, []
header_done = False
for number, raw in enumerate(lines, 1):
    line = raw.strip()
    if not header_done and line in ("# Listing of Parameters",
                                    "# ---------------------"):
        continue
    header_done = True
    if not line:
        continue
    if line.startswith("#"):
        comment.append(line[1:].strip())
    elif line.startswith("subsection "):
        path.append(line[len("subsection "):].strip())
        comment = []
    elif line == "end":
        if not path:
            sys.exit("line %d: 'end' outside a subsection" % number)
        path.pop()
        comment = []
    elif line.startswith("set ") and "=" in line:
        name, value = line[4:].split("=", 1)
        key = " / ".join(path) if path else "(top level)"
        if key not in sections:
            sections[key] = []
            order.append(key)
        sections[key].append((name.strip(), value.strip(), " ".join(comment)))
        comment = []
    else:
        sys.exit("line %d: cannot read '%s'" % (number, raw))
if path:
    sys.exit("unterminated subsection " + " / ".join(path))


def cell(text):
    return text.replace("|", "\\|")


out = ["# Parameter reference", "",
       "Generated from `deepdraw --print-parameters` by "
       "`scripts/generate_parameter_doc.sh`; do not edit by hand, rerun the "
       "script after changing a parameter (ctest `input/parameter_doc_current` "
       "fails while this file is out of date).", "",
       "A parameter file only needs the entries that differ from the defaults "
       "below; `deepdraw --print-parameters > all.prm` gives a complete, "
       "commented file to start from. Units: mm, N, MPa.", ""]
for key in order:
    out += ["## `subsection %s`" % key.replace(" / ", "` / `subsection "), "",
            "| Parameter | Default | Description |", "|---|---|---|"]
    for name, value, text in sections[key]:
        default = "`%s`" % cell(value) if value else "(empty)"
        out.append("| `%s` | %s | %s |" % (cell(name), default, cell(text)))
    out.append("")
sys.stdout.write("\n".join(out))
EOF

if [ "$output" = "-" ]; then
  cat "$listing.md"
else
  cat "$listing.md" > "$output"
  echo "generate_parameter_doc: wrote $output"
fi
