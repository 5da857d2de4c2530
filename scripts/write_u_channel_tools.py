#!/usr/bin/env python3
"""Write the tools of the NUMISHEET'93 2D draw bending (U-channel) as tool files.

The half model of prm/u_channel.prm (symmetry plane x = 0): the strip lies
along x in the frame of the blank (D1: bottom at z = 0, top at z = T), the
tools are the channel profiles of the benchmark extruded along y over
[Y0, Y1], which covers any strip width up to 35 mm. Dimensions (doc/
decisions.md D154): punch half width 35 mm with a 5 mm corner radius, die
opening half width 36 mm (a gap of 1 mm beside the punch, 0.22 mm beyond
the sheet) with a 5 mm shoulder radius, blank holder over the flange from
the end of the die shoulder (x = 41 mm) outwards.

Each tool is a chain of patches along its profile, degree 1 across the
strip; the straight parts are degree 1, the radii quarter circles, exact as
quadratic rational Bezier curves (weights 1, sqrt(2)/2, 1, doc/
tool_files.md). The profile runs along u, y along v, in the direction
that turns the normal x_u x x_v towards the sheet: -z under the punch and
the holder, +x on the punch's side; +z on the die's top, -x on its inner
wall. Neighbouring patches share their edges (classified 'shared' by the
reader); the holder's inner edge at x = 41 mm is free, as the square cup's.

  scripts/write_u_channel_tools.py [DIRECTORY]   # default prm/tools/u_channel

Check with `deepdraw --check prm/u_channel.prm`, which prints each tool's
box.
"""

import math
import pathlib
import sys

T = 0.78              # sheet thickness, mm
PUNCH_HALF = 35.0     # punch half width
PUNCH_RADIUS = 5.0    # punch corner radius
DIE_HALF = 36.0       # die opening half width
DIE_RADIUS = 5.0      # die shoulder radius
TOOL_DEPTH = 100.0    # height of the punch's side and of the die's wall
OUTER = 200.0         # outer end of the die top and the holder (strip: 175)
Y0, Y1 = -5.0, 40.0   # extent of the tools across the strip
W = math.sqrt(2.0) / 2.0


def fmt(v):
    return repr(float(v))


def patch(profile, weights, y_first, y_second, edges=None):
    """A patch: the profile points (x, z) along u, extruded from y_first
    (v = 0) to y_second (v = 1)."""
    lines = ["patch", "degrees %d 1" % (len(profile) - 1)]
    for y in (y_first, y_second):
        for (x, z), w in zip(profile, weights):
            lines.append("%s %s %s %s" % (fmt(x), fmt(y), fmt(z), fmt(w)))
    if edges:
        lines.append("edges " + edges)
    lines.append("end")
    return "\n".join(lines)


def line(a, b):
    return [a, b], [1.0, 1.0]


def quarter(start, corner, end):
    return [start, corner, end], [1.0, W, 1.0]


def punch():
    """Profile from the axis outwards along the flat, round the corner, up
    the side; v along -y, so that the normal is -z on the flat."""
    z0 = T
    r = PUNCH_RADIUS
    flat = PUNCH_HALF - r
    parts = [line((0.0, z0), (flat, z0)),
             quarter((flat, z0), (PUNCH_HALF, z0), (PUNCH_HALF, z0 + r)),
             line((PUNCH_HALF, z0 + r), (PUNCH_HALF, z0 + TOOL_DEPTH))]
    # the flat's edge u = 0 lies on the symmetry plane x = 0
    edges = ["symmetry automatic automatic automatic", None, None]
    return parts, edges, (Y1, Y0)


def die():
    """Profile from the bottom of the inner wall up, round the shoulder,
    out along the top; v along +y, so that the normal is +z on the top."""
    r = DIE_RADIUS
    parts = [line((DIE_HALF, -TOOL_DEPTH), (DIE_HALF, -r)),
             quarter((DIE_HALF, -r), (DIE_HALF, 0.0), (DIE_HALF + r, 0.0)),
             line((DIE_HALF + r, 0.0), (OUTER, 0.0))]
    return parts, [None, None, None], (Y0, Y1)


def holder():
    """The flat over the flange from the end of the die shoulder outwards;
    v along -y (normal -z). Its inner edge (u = 0) is free."""
    parts = [line((DIE_HALF + DIE_RADIUS, T), (OUTER, T))]
    return parts, ["free automatic automatic automatic"], (Y1, Y0)


def write(directory, name, title, tool, comment):
    parts, edges, (ya, yb) = tool
    text = ["# %s" % line_ for line_ in comment.splitlines()]
    text.append("# Written by scripts/write_u_channel_tools.py; do not edit.")
    text.append("tool " + title)
    for (profile, weights), e in zip(parts, edges):
        text.append(patch(profile, weights, ya, yb, e))
    path = directory / (name + ".tool")
    path.write_text("\n".join(text) + "\n")
    return path


def main(argv):
    directory = pathlib.Path(argv[1] if len(argv) > 1
                             else pathlib.Path(__file__).resolve().parent.parent
                             / "prm" / "tools" / "u_channel")
    directory.mkdir(parents=True, exist_ok=True)
    common = ("NUMISHEET'93 2D draw bending, half model (x >= 0), profile "
              "extruded along y\nover [%g, %g] mm; doc/decisions.md D154."
              % (Y0, Y1))
    written = [
        write(directory, "punch", "punch", punch(),
              common + "\nPunch: half width %g mm, corner radius %g mm, "
              "bottom at z = %g mm (on the sheet)." %
              (PUNCH_HALF, PUNCH_RADIUS, T)),
        write(directory, "die", "die", die(),
              common + "\nDie: opening half width %g mm, shoulder radius "
              "%g mm, top at z = 0." % (DIE_HALF, DIE_RADIUS)),
        write(directory, "holder", "holder", holder(),
              common + "\nBlank holder: flat at z = %g mm from x = %g mm "
              "outwards." % (T, DIE_HALF + DIE_RADIUS)),
    ]
    for path in written:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
