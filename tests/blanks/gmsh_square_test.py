#!/usr/bin/env python3
"""A Gmsh blank of the square outline gives the square-cup results of the
built-in rectangle (issue 16): the short square cup (tests/regression/
square_cup_short.prm: 12 x 12 x 2 elements, 0 -> 3 mm in 0.1 mm
increments, residuals to 1e-6) run with Blank outline = rectangle and with
Blank outline = gmsh on a two-dimensional mesh of the same 12 x 12 grid,
written here as a Gmsh 2.2 file with its nodes and quadrilaterals in an
order of their own (columns first, every quadrilateral starting at another
corner), so that deal.II numbers vertices, cells and dofs differently.
punch_force.csv, draw_in.csv and the thickness profiles must agree at every
row to 1e-8 of each column's largest magnitude: the two runs solve the same
equations, and only the summation order differs (measured: see the printed
largest difference, 3.2e-11 when written; a wrong boundary id, outline point or
thickness location shows up at 1e-3 or more).

    gmsh_square_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402

TOLERANCE = 1e-8
N = 12
SIZE = 75.0
TABLES = ("punch_force.csv", "draw_in.csv", "thickness_OX_3mm.csv",
          "thickness_OY_3mm.csv", "thickness_OD_3mm.csv",
          "thickness_OX_1.5mm.csv", "thickness_OD_1.5mm.csv")


def write_msh(path):
    """The N x N grid on [0, SIZE]^2, nodes numbered column by column."""
    h = SIZE / N
    number = {}
    nodes = []
    for i in range(N + 1):
        for j in range(N + 1):
            number[(i, j)] = len(nodes) + 1
            nodes.append((i * h, j * h))
    quads = []
    for j in range(N):
        for i in range(N):
            ring = [number[(i, j)], number[(i + 1, j)],
                    number[(i + 1, j + 1)], number[(i, j + 1)]]
            shift = (i + 2 * j) % 4
            quads.append(ring[shift:] + ring[:shift])
    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$Nodes",
             str(len(nodes))]
    lines += ["%d %.17g %.17g 0" % (k + 1, x, y)
              for k, (x, y) in enumerate(nodes)]
    lines += ["$EndNodes", "$Elements", str(len(quads))]
    lines += ["%d 3 2 1 1 %s" % (k + 1, " ".join(map(str, q)))
              for k, q in enumerate(quads)]
    lines += ["$EndElements"]
    path.write_text("\n".join(lines) + "\n")


def main():
    args, source, work = script_test.start(__doc__)
    short = source / "tests" / "regression" / "square_cup_short.prm"
    write_msh(work / "square.msh")
    (work / "rectangle.prm").write_text(
        "include %s\nsubsection Output\n  set Output directory = rectangle\n"
        "end\n" % short)
    (work / "gmsh.prm").write_text(
        "include %s\nsubsection Geometry\n  set Blank outline = gmsh\n"
        "  set Mesh file = square.msh\nend\n"
        "subsection Output\n  set Output directory = gmsh\nend\n" % short)
    for name in ("rectangle", "gmsh"):
        script_test.run([args.deepdraw, "--quiet", name + ".prm"], work, 2000)
    failures, worst = script_test.compare_tables(
        work / "rectangle", work / "gmsh", TABLES, TOLERANCE)
    print("largest relative difference: %.3g" % worst)
    for failure in failures:
        print("FAILED:", failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
