#!/usr/bin/env python3
"""`Linear solver/Type = AMG` on a small contact problem with stick and
slip (issue 30, D193): tests/contact/newton_cylinder_friction.prm, the rigid
cylinder pressed into an elastic block of 30 x 1 x 20 cells (3 906
displacement unknowns: two levels of the hierarchy at the default coarse
size of 2 000) with friction mu = 0.162, Newton tolerances 1e-11. Run four
times:
- with MUMPS, the reference;
- with AMG (GMRES to 1e-10 with smoothed aggregation): the systems must be
  solved by GMRES with no fallback to MUMPS, stick and slip pairs must
  occur, and the run must be the reference run to TOLERANCE of each table's
  largest number (every CSV: the same Newton iterations and contact states,
  forces, reactions, residuals, but for statistics.csv's count of
  factorised unknowns, 0 with AMG; measured 1.2e-12: the solves differ by
  the GMRES tolerance, far below the Newton tolerance);
- with AMG allowed 11 GMRES iterations: some systems fall back, and an
  increment whose last system GMRES solved writes factorized_unknowns 0
  after one that factorised (mixed_solves);
- with AMG allowed one GMRES iteration, which cannot reach 1e-10: every
  system falls back to MUMPS, so the run must be the reference run byte for
  byte (every CSV table but the wall times).
The block with a force-controlled tool (the holder's position bordering the
displacements): the short square cup of regression/square_cup_short.prm to
1 mm (12 x 12 x 2, 1 521 displacement unknowns, below the coarse size, so
that the hierarchy is one level factorised by KLU and the V-cycle is M^-1
itself). The block factorisation of the preconditioner is then exact, and
GMRES must converge in one iteration for every system and for W = M^-1 C
in exact arithmetic; round-off of the scaled matrix's factorisation leaves
some residuals above the default tolerance 1e-8 after one, so at most two
each are allowed (measured: 151 iterations for 67 systems and 67 W), and no
fallback; every CSV within
TOLERANCE_CUP of the MUMPS run (measured 1.8e-13; the cup's Newton
tolerance is 1e-6, and the two exact solvers differ by round-off).

    amg_solver_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402
from script_test import run  # noqa: E402

TOLERANCE = 1e-11
TOLERANCE_CUP = 1e-8


def write_prm(source, work, name, settings, case=("contact",
                                                   "newton_cylinder_friction")):
    extra = ""
    if case[0] == "regression":
        extra = ("subsection Process\n  set Final load = 1\nend\n"
                 "subsection Output\n  set Thickness profile travels = 1\n"
                 "end\n")
    return script_test.write_linear_solver_case(
        work, name, "%s.prm" % source.joinpath("tests", *case), settings,
        extra)


def amg_counts(log):
    match = re.search(r"linear solver: (\d+) AMG hierarchies, (\d+) GMRES "
                      r"solves \((\d+) iterations in all\), (\d+) systems "
                      r"solved by MUMPS", log)
    return tuple(int(g) for g in match.groups()) if match else None


def contact_states(directory):
    rows = script_test.csv_rows(directory / "statistics.csv")
    return (max(int(r["stick_pairs"]) for r in rows),
            max(int(r["slip_pairs"]) for r in rows))


def nothing_factorised(directory):
    """With every system solved by GMRES, statistics.csv's
    factorized_unknowns is 0 in every increment (no factorisation)."""
    rows = script_test.csv_rows(directory / "statistics.csv")
    factorised = [r["factorized_unknowns"] for r in rows
                  if r["factorized_unknowns"] != 0.]
    if factorised:
        return ["%s: factorized_unknowns %s with no fallback, expected 0"
                % (directory.name, factorised[:3])]
    return []


def mixed_solves(deepdraw, source, work):
    """AMG allowed 11 GMRES iterations (the systems need 11.4 on average):
    some systems fall back to MUMPS, the others do not, so an increment
    whose last system GMRES solved follows one that factorised. Its
    factorized_unknowns must be 0, which the count of an earlier fallback
    never is; every other row the factorised size."""
    prm = write_prm(source, work, "mixed.prm",
                    [("Type", "AMG"), ("AMG tolerance", "1e-10"),
                     ("AMG iterations", "11")])
    counts = amg_counts(run([deepdraw, prm, "--output-directory", "mixed"],
                            work, tail=300))
    print("mixed: hierarchies, GMRES solves, iterations, fallbacks:", counts)
    if counts is None or counts[1] == 0 or counts[3] == 0:
        return ["mixed: expected systems solved by GMRES and by MUMPS: %s"
                % (counts,)]
    rows = script_test.csv_rows(work / "mixed" / "statistics.csv")
    sizes = [int(r["factorized_unknowns"]) for r in rows]
    size = max(sizes)
    if any(n not in (0, size) for n in sizes) or not any(
            sizes[i] == 0 and size in sizes[:i] for i in range(len(sizes))):
        return ["mixed: factorized_unknowns %s, expected 0 after a GMRES "
                "solve and %d after a factorisation, a 0 after a %d"
                % (sizes, size, size)]
    return []


def main():
    args, source, work = script_test.start(__doc__)
    failures = []
    data = work / "data"
    if not data.exists():
        data.symlink_to(source / "tests" / "contact" / "data")
    direct = write_prm(source, work, "direct.prm", [])
    amg = write_prm(source, work, "amg.prm",
                    [("Type", "AMG"), ("AMG tolerance", "1e-10")])
    fallback = write_prm(source, work, "fallback.prm",
                         [("Type", "AMG"), ("AMG tolerance", "1e-10"),
                          ("AMG iterations", "1")])
    run([args.deepdraw, direct, "--output-directory", "direct"], work,
        tail=300)

    log = run([args.deepdraw, amg, "--output-directory", "amg"], work,
              tail=300)
    counts = amg_counts(log)
    print("AMG: hierarchies, GMRES solves, iterations, fallbacks:", counts)
    if counts is None or counts[1] == 0 or counts[3] != 0:
        failures.append("expected every condensed system solved by GMRES "
                        "with AMG and no fallback: %s" % (counts,))
    stick, slip = contact_states(work / "amg")
    if stick == 0 or slip == 0:
        failures.append("expected pairs in stick and in slip, found at most "
                        "%d and %d" % (stick, slip))
    failures += script_test.close_tables(
        work / "direct", work / "amg", "the MUMPS run", TOLERANCE,
        ("symbolic_analyses", "factorized_unknowns"))
    failures += nothing_factorised(work / "amg")

    failures += mixed_solves(args.deepdraw, source, work)

    log = run([args.deepdraw, fallback, "--output-directory", "fallback"],
              work, tail=300)
    counts = amg_counts(log)
    if counts is None or counts[1] != 0 or counts[3] == 0:
        failures.append("one GMRES iteration allowed: %s, expected every "
                        "system solved by MUMPS" % (counts,))
    failures += script_test.same_tables(work / "direct", work / "fallback",
                                        "the MUMPS run")

    cup = ("regression", "square_cup_short")
    prm = work / "prm"
    if not prm.exists():
        prm.symlink_to(source / "prm")
    cup_direct = write_prm(source, work, "cup_direct.prm", [], cup)
    cup_amg = write_prm(source, work, "cup_amg.prm", [("Type", "AMG")], cup)
    run([args.deepdraw, cup_direct, "--output-directory", "cup_direct"],
        work, tail=300)
    log = run([args.deepdraw, cup_amg, "--output-directory", "cup_amg"],
              work, tail=300)
    counts = amg_counts(log)
    print("cup, AMG: hierarchies, GMRES solves, iterations, fallbacks:",
          counts)
    if counts is None or counts[3] != 0 or counts[1] != counts[0] \
            or counts[2] > 4 * counts[0]:
        failures.append("cup: expected at most two GMRES iterations for "
                        "each system and each W, no fallback: %s" % (counts,))
    failures += script_test.close_tables(
        work / "cup_direct", work / "cup_amg", "the MUMPS run", TOLERANCE_CUP,
        ("symbolic_analyses", "factorized_unknowns"))
    failures += nothing_factorised(work / "cup_amg")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
