// LinearSolverParameters: the entries of `subsection Linear solver`, their
// checks against each other, and the GMRES budget with kept factors (D228);
// the solver itself is in linear_solver.cc.
#include <algorithm>
#include <cmath>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/integer_or_auto.h>
#include <deepdraw/parallel/ranks.h>
#include <deepdraw/solver/linear_solver.h>

namespace deepdraw
{
  namespace solver
  {
    void
    LinearSolverParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.declare_entry("Type",
                        "MUMPS",
                        Patterns::Selection("UMFPACK|MUMPS|KLU|AMG"),
                        "Solver of the Newton system: MUMPS "
                        "(multifrontal LU, called directly; 10-15 % faster "
                        "than UMFPACK on the square-cup meshes, "
                        "doc/decisions.md D96), UMFPACK (SuiteSparse, "
                        "called directly), KLU (through Trilinos Amesos), or "
                        "AMG: GMRES preconditioned by smoothed-aggregation "
                        "multigrid (Trilinos ML, the rigid-body modes as "
                        "near-null space) for the condensed system, MUMPS "
                        "for the systems it does not take (D193). AMG needs "
                        "Condense contact multipliers.");
      prm.declare_entry("Leave out decoupled unknowns",
                        "false",
                        Patterns::Bool(),
                        "Factorise the Newton matrix without the unknowns "
                        "whose row and column hold only the diagonal: the "
                        "contact forces of open pairs and the constrained "
                        "dofs (the same solution, a smaller system, but a "
                        "worse fill-reducing ordering and a new analysis "
                        "whenever the open set changes: 13 % slower on the "
                        "square cup; doc/decisions.md D60, D64). Applies "
                        "to the whole system only: with Condense contact "
                        "multipliers it is used for the solves that fall "
                        "back to the whole system.");
      prm.declare_entry(
        "Condense contact multipliers",
        "true",
        Patterns::Bool(),
        "Eliminate the contact forces exactly before the factorisation: "
        "the factorised matrix has the displacements only, bordered by the "
        "positions of force-controlled tools, and the Newton step is the "
        "same (doc/decisions.md D90). Nodes touching two tools at once "
        "fall back to the whole system for that solve.");
      prm.declare_entry(
        "Reuse factorisation",
        "auto",
        Patterns::Selection("true|false|auto"),
        "Within an increment, solve each Newton system after the first by "
        "GMRES preconditioned with the last factorisation, only as exactly "
        "as Newton needs (Eisenstat-Walker forcing term), and factorise "
        "only when GMRES does not get there in `Reuse iterations` "
        "(doc/decisions.md D185). The converged increments are the same "
        "to the Newton tolerances. 'auto': for factorised systems of at "
        "least `Reuse threshold` unknowns, where it saved 14-18 % of whole "
        "runs; smaller ones are factorised every time (D206). Not with "
        "Type AMG, which factorises nothing.");
      prm.declare_entry("Reuse threshold",
                        "20000",
                        Patterns::Integer(1, 1000000000),
                        "Reuse factorisation = auto: the number of "
                        "unknowns of a factorised system (after the "
                        "condensation of the contact forces) from which "
                        "the factorisation is reused (D206).");
      prm.declare_entry("Forcing term",
                        "0.1",
                        Patterns::Double(1e-12, 0.9),
                        "Largest relative linear residual |b - A x| / |b| "
                        "at which GMRES with a kept factorisation stops; "
                        "the Eisenstat-Walker term tightens it as Newton "
                        "converges, down to Smallest forcing term (D185).");
      prm.declare_entry("Smallest forcing term",
                        "0.1",
                        Patterns::Double(1e-12, 0.9),
                        "Lower bound of the Eisenstat-Walker forcing term. "
                        "Equal to Forcing term by default: tightening cost "
                        "more factorisations than it saved Newton "
                        "iterations on the square cup (D185).");
      prm.declare_entry(
        "Reuse iterations",
        "auto",
        io::IntegerOrAuto(1, 1000),
        "GMRES iterations with a kept factorisation before the system is "
        "factorised afresh (D185). 'auto': 10 on systems of up to 23 409 "
        "unknowns (50 x 50 x 2 cells), growing as the 0.4th power of the "
        "unknowns above (17 on 100 x 100 x 2, 41 on 300 x 300 x 2), as "
        "the cost of a factorisation grows against that of an iteration "
        "(D227, D228).");
      prm.declare_entry(
        "Factorisation precision",
        "auto",
        Patterns::Selection("double|single|auto"),
        "Arithmetic of MUMPS' factors. 'single': single precision, about a "
        "third less time per factorisation on 100 x 100 x 2; each solve is "
        "refined by GMRES in double, right "
        "preconditioned with those factors, to `Single precision "
        "tolerance` after a factorisation and to the forcing term with "
        "kept factors, and a system the refinement does not solve is "
        "factorised again in double. The first increment of a stage "
        "factorises in double: its contact states start inside the tools "
        "and its Newton path is sensitive to round-off (doc/decisions.md "
        "D226). 'auto': single precision where Reuse factorisation = auto "
        "reuses factorisations (systems of at least Reuse threshold "
        "unknowns), double elsewhere. 'single' needs Type MUMPS.");
      prm.declare_entry("Single precision tolerance",
                        "1e-3",
                        Patterns::Double(1e-12, 0.5),
                        "Factorisation precision single: relative linear "
                        "residual |b - A x| / |b| to which GMRES refines the "
                        "solve after a single-precision factorisation "
                        "(D226).");
      prm.declare_entry("AMG tolerance",
                        "1e-8",
                        Patterns::Double(1e-14, 0.1),
                        "Type AMG: GMRES stops at |b - A x| <= this "
                        "times |b| (D193).");
      prm.declare_entry("AMG iterations",
                        "300",
                        Patterns::Integer(1, 10000),
                        "Type AMG: GMRES iterations after which the system "
                        "is solved by MUMPS instead (D193).");
      prm.declare_entry("AMG coarse size",
                        "2000",
                        Patterns::Integer(10, 1000000),
                        "Type AMG: the multigrid hierarchy is coarsened "
                        "until a level has at most this many unknowns; that "
                        "level is factorised (KLU). A system this small is "
                        "solved exactly by the preconditioner (D193).");
      prm.leave_subsection();
    }


    void
    LinearSolverParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      type                 = prm.get("Type");
      leave_out_decoupled  = prm.get_bool("Leave out decoupled unknowns");
      condense_multipliers = prm.get_bool("Condense contact multipliers");
      const std::string reuse_text = prm.get("Reuse factorisation");
      reuse                        = reuse_text == "true"    ? Reuse::always
                                     : reuse_text == "false" ? Reuse::never
                                                             : Reuse::automatic;
      reuse_threshold              = prm.get_integer("Reuse threshold");
      forcing_term                 = prm.get_double("Forcing term");
      smallest_forcing_term        = prm.get_double("Smallest forcing term");
      if (smallest_forcing_term > forcing_term)
        throw InputError("Linear solver/Smallest forcing term = "
                         + prm.get("Smallest forcing term")
                         + " is larger than Linear solver/Forcing term = "
                         + prm.get("Forcing term")
                         + ": allowed is at most the forcing term");
      reuse_iterations                 = prm.get("Reuse iterations") == "auto"
                                           ? automatic_reuse_iterations
                                           : prm.get_integer("Reuse iterations");
      const std::string precision_text = prm.get("Factorisation precision");
      precision = precision_text == "double"   ? Precision::double_only
                  : precision_text == "single" ? Precision::single
                                               : Precision::automatic;
      single_precision_tolerance = prm.get_double("Single precision tolerance");
      if (precision == Precision::single && type != "MUMPS")
        throw InputError("Linear solver/Factorisation precision = single "
                         "needs Linear solver/Type = MUMPS (given: "
                         + type + "); allowed with " + type
                         + " is double or auto");
      amg.relative_tolerance = prm.get_double("AMG tolerance");
      amg.max_iterations     = prm.get_integer("AMG iterations");
      amg.coarse_size        = prm.get_integer("AMG coarse size");
      if (iterative() && !condense_multipliers)
        throw InputError("Linear solver/Type = AMG needs Linear solver/"
                         "Condense contact multipliers = true (AMG solves "
                         "the condensed system only)");
      if (iterative() && reuse == Reuse::always)
        throw InputError("Linear solver/Type = AMG cannot be combined with "
                         "Linear solver/Reuse factorisation = true: allowed "
                         "with AMG is false");
      // KLU and the AMG hierarchy are built on Trilinos' serial maps
      // (D199); UMFPACK and the decoupled unknowns' search need the whole
      // matrix, which no rank holds (D214).
      if (parallel::n_ranks() > 1 && type != "MUMPS")
        throw InputError("Linear solver/Type = " + type
                         + " runs on one MPI "
                           "rank; allowed under mpirun is MUMPS (factorised "
                           "across the ranks)");
      if (parallel::n_ranks() > 1 && leave_out_decoupled)
        throw InputError("Linear solver/Leave out decoupled unknowns = true "
                         "runs on one MPI rank; allowed under mpirun is "
                         "false");
      prm.leave_subsection();
    }


    unsigned int
    LinearSolverParameters::gmres_budget(const std::size_t n) const
    {
      if (reuse_iterations != automatic_reuse_iterations)
        return reuse_iterations;
      // D227: the best budget measured on 50 x 50 x 2 (23 409 unknowns) is
      // 10; the break-even against a factorisation grew as n^0.4 from
      // there to 100 x 100 x 2.
      constexpr double reference_unknowns = 23409.;
      const double     grown = 10. * std::pow(n / reference_unknowns, 0.4);
      return std::max(10u, static_cast<unsigned int>(std::lround(grown)));
    }
  } // namespace solver
} // namespace deepdraw
