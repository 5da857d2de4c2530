#!/usr/bin/env python3
"""A run on 1, 2 and 3 MPI ranks is the same simulation (issue 29, D199):
the short square cup of restart/kill_and_resume_test (8 x 8 x 2 cells, 15
increments, a checkpoint after each) without mpirun and with 2 and 3 ranks
(oversubscribed); the same cup refined through the thickness (cut_z) by the
plastic strain jump, with 1 and 2 ranks, and stopped at load 0.8 on 2 ranks
and resumed on 1 and on 3; and a 2-rank run stopped at load 0.8 and resumed
with 1, 2 and 3 ranks.

Expectations, independent of the program's own numbers:
- the same Newton path: every increment with the same number of iterations
  and the same count of contact-state changes in each (newton.csv), so the
  same contact states;
- every CSV value within 1e-8 of the larger or of the table's largest
  magnitude (the issue's bound): the ranks sum the element contributions
  in another order, and MUMPS factorises in another order across ranks, so
  the last bits differ (measured: 4e-11);
- the sheet's VTU output as a .pvtu record per output step naming one
  piece per rank, every piece on disk, the pieces' cells adding up to those
  of the one-rank run's VTU;
- the cell fields of the material state in the pieces (each rank writes
  those of the cells whose state it holds, D217) the one-rank run's, also
  after the cut_z refinement moved cells between the ranks;
- the resumed runs within the same 1e-8 of the uninterrupted 2-rank run,
  whatever their rank count (a checkpoint holds every cell's state,
  gathered on rank 0, so it does not depend on the ranks). Not bit for bit even with 2
  ranks: a run that ends at a final load and is extended by a resume is not
  bit-identical to the uninterrupted run on one rank either (6 cells of
  newton.csv differ in the 10th digit, measured), unlike a killed run (D55).

    ranks_agree_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import re
import shutil

from mpirun_tools import SHORT_CUP, newton_path, read_vtu, run, script_test

# The square cup's punch is 70 mm wide: a closed pair of the top surface
# beyond 40 mm of its axis is the holder's.
HOLDER_FROM = 40.

CUT_Z = """include {base}
subsection Adaptivity
  set Enabled                 = true
  set Refinement interval     = 4
  set Maximum level           = 1
  set Maximum number of cells = 600
  set Indicator               = plastic strain jump
  set Jump threshold          = 1e-5
  set Refinement              = cut_z
end
"""

TO_0_8 = """include {base}
subsection Process
  set Final load = 0.8
end
"""


def compare(failures, expected, actual, what):
    if newton_path(expected) != newton_path(actual):
        failures.append(f"{what}: another Newton path (newton.csv: "
                        "iterations or contact changes)")
    failures += script_test.close_tables(expected, actual, what,
                                         relative=1e-8)


def cells(path):
    """NumberOfCells in the pieces of a VTU file."""
    return sum(int(n) for n in
               re.findall(r'NumberOfCells="(\d+)"', path.read_text()))


def check_pieces(failures, serial, parallel, ranks):
    """Every sheet output of the run on `ranks` ranks is a .pvtu naming one
    piece per rank, each on disk, with the serial VTU's cells between them
    (D201)."""
    records = sorted(parallel.glob("solution-*.pvtu"))
    if len(records) != len(list(serial.glob("solution-*.vtu"))):
        failures.append(f"{parallel.name}: {len(records)} .pvtu records")
    for record in records:
        pieces = re.findall(r'Piece Source="([^"]+)"', record.read_text())
        missing = [p for p in pieces if not (parallel / p).is_file()]
        whole = serial / record.name.replace(".pvtu", ".vtu")
        split = sum(cells(parallel / p) for p in pieces if p not in missing)
        if len(pieces) != ranks or missing or split != cells(whole):
            failures.append(f"{record.name}: {len(pieces)} pieces, missing "
                            f"{missing}, {split} cells against "
                            f"{cells(whole)}")
    print(f"{parallel.name}: {len(records)} .pvtu records of {ranks} pieces")


def check_material_fields(failures, serial, parallel):
    """The material state in the VTU output, written by the rank that holds
    each cell's state (D217): at the last output step, the values of the
    cell fields equivalent_plastic_strain and stress_xx over all pieces,
    sorted, against the one-rank VTU's, sorted (sorting moves no value by
    more than the largest difference of two matched cells). Allowed: 1e-6
    of the field's largest magnitude, a few float32 roundings of values
    that agree to the tables' 1e-8."""
    record = sorted(parallel.glob("solution-*.pvtu"))[-1]
    _, whole = read_vtu(serial / record.name.replace(".pvtu", ".vtu"))
    split = {}
    for piece in re.findall(r'Piece Source="([^"]+)"', record.read_text()):
        for name, values in read_vtu(parallel / piece)[1].items():
            split.setdefault(name, []).extend(values)
    for name in ("equivalent_plastic_strain", "stress_xx"):
        expected, actual = sorted(whole[name]), sorted(split.get(name, []))
        scale = max(abs(v) for v in expected)
        worst = max((abs(a - b) for a, b in zip(expected, actual)),
                    default=float("inf"))
        print(f"{parallel.name} {record.name}: {name} worst difference "
              f"{worst:.3g} of largest {scale:.3g}")
        if len(expected) != len(actual) or scale == 0. \
                or worst > 1e-6 * scale:
            failures.append(f"{parallel.name}: {name} of the pieces differs "
                            f"from one rank's by {worst:.3g} "
                            f"(largest {scale:.3g})")


def ranks_of_points(directory, record):
    """{point (rounded to 1e-6 mm): set of ranks whose piece holds it} and
    {point: its contact_status} of the pieces of a .pvtu record."""
    ranks, contact = {}, {}
    pieces = re.findall(r'Piece Source="([^"]+)"', record.read_text())
    for rank, piece in enumerate(pieces):
        points, fields = read_vtu(directory / piece)
        for point, status in zip(points, fields["contact_status"]):
            key = tuple(round(c, 6) for c in point)
            ranks.setdefault(key, set()).add(rank)
            contact[key] = status
    return ranks, contact


def check_partition(failures, parallel, ranks, holder_from):
    """Contact across the partition (issue 29): at the last output step,
    closed contact pairs (contact_status 1 or 2) at nodes shared by cells
    of two ranks, and the holder's closed pairs (top-surface nodes beyond
    holder_from mm of the punch axis, where the punch, 35 mm from it, cannot
    touch) at nodes of several ranks' cells. The runs' tables are compared
    with the one-rank run in compare(); here it is shown that the cases the
    issue names occur in them."""
    record = sorted(parallel.glob("solution-*.pvtu"))[-1]
    owners, status = ranks_of_points(parallel, record)
    closed = [p for p, s in status.items() if s > 0]
    on_boundary = [p for p in closed if len(owners[p]) > 1]
    holder = [p for p in closed
              if p[2] > 0.5 and max(abs(p[0]), abs(p[1])) > holder_from]
    holder_ranks = set().union(*(owners[p] for p in holder)) if holder \
        else set()
    print(f"{parallel.name} ({record.name}): {len(closed)} closed pairs, "
          f"{len(on_boundary)} at nodes of two ranks' cells; the holder's "
          f"{len(holder)} on ranks {sorted(holder_ranks)}")
    if not on_boundary:
        failures.append(f"{parallel.name}: no closed pair on the partition "
                        "boundary")
    if len(holder_ranks) < 2:
        failures.append(f"{parallel.name}: the holder's pairs on ranks "
                        f"{sorted(holder_ranks)} only")


def must_run(failures, ranks, args, work, *arguments):
    code, _ = run(ranks, args.deepdraw, work, *arguments)
    if code != 0:
        failures.append(f"{ranks} ranks, {' '.join(map(str, arguments))}: "
                        f"exit code {code}")
    return code == 0


def main():
    args, _, work = script_test.start(__doc__)
    failures = []

    for ranks, name in ((0, "one"), (2, "two"), (3, "three")):
        must_run(failures, ranks, args, work, SHORT_CUP,
                 "--output-directory", name, "--quiet")
    compare(failures, work / "one", work / "two", "2 ranks against 1")
    compare(failures, work / "one", work / "three", "3 ranks against 1")
    check_pieces(failures, work / "one", work / "two", 2)
    check_pieces(failures, work / "one", work / "three", 3)
    check_material_fields(failures, work / "one", work / "three")
    check_partition(failures, work / "three", 3, HOLDER_FROM)

    (work / "cut_z.prm").write_text(CUT_Z.format(base=SHORT_CUP))
    for ranks, name in ((0, "cut_z_one"), (2, "cut_z_two")):
        must_run(failures, ranks, args, work, "cut_z.prm",
                 "--output-directory", name, "--quiet")
    refinements = script_test.csv_rows(work / "cut_z_one" / "adaptivity.csv")
    print(f"cut_z: {len(refinements)} refinements, cells "
          f"{[int(r['cells_after']) for r in refinements]}")
    if not refinements:
        failures.append("the cut_z run refined nothing")
    compare(failures, work / "cut_z_one", work / "cut_z_two",
            "cut_z refinement, 2 ranks against 1")
    check_material_fields(failures, work / "cut_z_one", work / "cut_z_two")

    # The refined run's checkpoint (gathered on rank 0 from the ranks' cells
    # after the refinements moved them, D217) resumed on 3 ranks, which
    # replay the refinements and keep their own cells, against the same
    # checkpoint resumed on one rank. Not against the uninterrupted run: a
    # run that ends at load 0.8 does not refine after its last increment
    # (D80), so the resumed runs refine once less.
    (work / "cut_z_to_0_8.prm").write_text(
        TO_0_8.format(base=work / "cut_z.prm"))
    if must_run(failures, 2, args, work, "cut_z_to_0_8.prm",
                "--output-directory", "cut_z_stopped", "--quiet"):
        for ranks, name in ((0, "cut_z_resumed_one"),
                            (3, "cut_z_resumed_three")):
            shutil.copytree(work / "cut_z_stopped", work / name)
            must_run(failures, ranks, args, work, "cut_z.prm",
                     "--output-directory", name, "--resume", "--quiet")
        compare(failures, work / "cut_z_resumed_one",
                work / "cut_z_resumed_three",
                "the cut_z run's 2-rank checkpoint resumed on 3 ranks "
                "against 1")

    (work / "to_0_8.prm").write_text(TO_0_8.format(base=SHORT_CUP))
    if must_run(failures, 2, args, work, "to_0_8.prm", "--output-directory",
                "stopped", "--quiet"):
        for ranks, name in ((2, "resumed_two"), (0, "resumed_one"),
                            (3, "resumed_three")):
            shutil.copytree(work / "stopped", work / name)
            must_run(failures, ranks, args, work, SHORT_CUP,
                     "--output-directory", name, "--resume", "--quiet")
        compare(failures, work / "two", work / "resumed_two",
                "a 2-rank checkpoint resumed on 2 ranks")
        compare(failures, work / "two", work / "resumed_one",
                "a 2-rank checkpoint resumed on 1 rank")
        compare(failures, work / "two", work / "resumed_three",
                "a 2-rank checkpoint resumed on 3 ranks")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
