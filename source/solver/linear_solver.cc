#include <algorithm>
#include <cmath>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/integer_or_auto.h>
#include <deepdraw/parallel/ranks.h>
#include <deepdraw/solver/bordered_amg_solver.h>
#include <deepdraw/solver/bordered_factorization.h>
#include <deepdraw/solver/linear_solver.h>
#include <stdexcept>

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


    LinearSolver::LinearSolver(const LinearSolverParameters &parameters)
        : parameters(parameters)
        , implementation(std::make_unique<BorderedFactorization>())
        , condensed_implementation(std::make_unique<BorderedFactorization>())
    {
      // Displacements only, in N/mm throughout: well scaled (D98).
      condensed_implementation->scale_matrix = false;
      if (parameters.iterative())
        amg = std::make_unique<BorderedAmgSolver>(parameters.amg);
    }


    LinearSolver::~LinearSolver() = default;


    void
    LinearSolver::reset_reduction(const bool continues_stage)
    {
      single_precision_allowed = continues_stage;
      for (BorderedFactorization *data :
           {implementation.get(), condensed_implementation.get()})
      {
        data->reduction_reset = true;
        data->umfpack.forget_analysis();
        // Each increment's first solve factorises (a resumed run repeats
        // the same arithmetic, D55).
        data->kept_size = 0;
      }
      previous_residual_norm = 0.;
    }


    LinearSolver::Statistics
    LinearSolver::statistics() const
    {
      // Both systems together (the condensed one and the whole one).
      Statistics total = solve_statistics;
      for (const BorderedFactorization *data :
           {implementation.get(), condensed_implementation.get()})
      {
        total.factorizations += data->statistics.factorizations;
        total.reductions += data->statistics.reductions;
        total.numeric_factorizations += data->statistics.numeric_factorizations;
        total.symbolic_analyses += data->umfpack.n_symbolic_analyses();
        if (data->mumps != nullptr)
          total.symbolic_analyses += data->mumps->n_symbolic_analyses();
      }
      return total;
    }


    void
    LinearSolver::set_multiplier_blocks(
      const SparsityPattern                      &pattern,
      const types::global_dof_index               n_displacements,
      const std::vector<MultiplierBlock>         &blocks,
      const std::vector<types::global_dof_index> &tool_positions,
      const std::vector<bool>                    &constrained,
      const std::vector<bool>                    &owned_rows)
    {
      implementation->owned_rows = owned_rows;
      if (!owned_rows.empty())
        implementation->full_pattern = nullptr; // a new reduction
      if (!parameters.condense_multipliers || blocks.empty())
      {
        condensation.reset();
        return;
      }
      condensation = std::make_unique<MultiplierCondensation>();
      // A new condensed pattern, possibly at the old one's address.
      condensed_implementation->full_pattern = nullptr;
      condensed_implementation->kept_size    = 0;
      condensation->initialize(pattern,
                               n_displacements,
                               blocks,
                               tool_positions,
                               constrained,
                               owned_rows);
      condensed_implementation->owned_rows
        = condensation->owned_condensed_rows();
    }


    void
    LinearSolver::solve(const SparseMatrix<double>                 &matrix,
                        const Vector<double>                       &rhs,
                        Vector<double>                             &solution,
                        const std::vector<types::global_dof_index> &bordered,
                        const std::vector<types::global_dof_index> &decoupled)
    {
      solve_statistics.unknowns = matrix.m();
      if (parameters.reuse != LinearSolverParameters::Reuse::never)
        update_forcing_term(rhs.l2_norm());
      if (condensation != nullptr && condensation->condense(matrix, rhs))
      {
        // The multipliers eliminated exactly (D90): the factorised matrix
        // is the displacement block, bordered by the tool positions.
        BorderedFactorization &condensed = *condensed_implementation;
        Vector<double>         condensed_solution;
        bool                   by_gmres = false;
        if (parameters.iterative())
          by_gmres = solve_condensed_iteratively(condensed_solution);
        else
          solve_with(condensed,
                     parameters.type,
                     condensation->matrix(),
                     condensation->rhs(),
                     condensed_solution,
                     condensation->condensed_tool_positions(),
                     {});
        condensation->expand(matrix, rhs, condensed_solution, solution);
        ++solve_statistics.condensed_solves;
        solve_statistics.factorized_unknowns
          = by_gmres ? 0 : condensed.statistics.factorized_unknowns;
        return;
      }
      solve_with(*implementation,
                 direct_type(),
                 matrix,
                 rhs,
                 solution,
                 bordered,
                 decoupled);
      solve_statistics.factorized_unknowns
        = implementation->statistics.factorized_unknowns;
    }


    void
    LinearSolver::set_rigid_body_modes(
      const std::vector<Point<3>>      &points,
      const std::vector<unsigned char> &components)
    {
      if (amg != nullptr)
        amg->amg().set_rigid_body_modes(points, components);
    }


    std::string
    LinearSolver::direct_type() const
    {
      return parameters.iterative() ? "MUMPS" : parameters.type;
    }


    bool
    LinearSolver::solve_condensed_iteratively(
      Vector<double> &condensed_solution)
    {
      // Stick and slip nodes scaled by their diagonal block (D96, D193).
      // A new hierarchy for every system: kept through an increment, it
      // took 2.7 times the linear-solve time on 100 x 100 x 2 (D193).
      const SparseMatrix<double> &matrix = condensation->matrix();
      amg->amg().set_scaled_nodes(condensation->coupled_nodes());
      bool solved
        = amg->initialize(matrix, condensation->condensed_tool_positions());
      ++solve_statistics.amg_hierarchies;
      solve_statistics.gmres_iterations += amg->last_iterations();
      if (solved)
      {
        solved = amg->solve(matrix, condensation->rhs(), condensed_solution);
        solve_statistics.gmres_iterations += amg->last_iterations();
      }
      if (solved)
      {
        ++solve_statistics.amg_solves;
        return true;
      }
      ++solve_statistics.amg_fallbacks;
      solve_with(*condensed_implementation,
                 direct_type(),
                 matrix,
                 condensation->rhs(),
                 condensed_solution,
                 condensation->condensed_tool_positions(),
                 {});
      return false;
    }


    void
    LinearSolver::solve_with(
      BorderedFactorization                      &data,
      const std::string                          &type,
      const SparseMatrix<double>                 &matrix,
      const Vector<double>                       &rhs,
      Vector<double>                             &solution,
      const std::vector<types::global_dof_index> &bordered,
      const std::vector<types::global_dof_index> &decoupled)
    {
      if (parameters.reuses_factorization(matrix.m())
          && data.has_kept_inverse(matrix.m())
          && solve_with_kept_factors(data, matrix, rhs, solution))
        return;
      if (single_precision_allowed
          && parameters.single_precision(type, matrix.m())
          && solve_in_single_precision(data,
                                       type,
                                       matrix,
                                       rhs,
                                       solution,
                                       bordered,
                                       decoupled))
        return;
      data.precision = FactorPrecision::double_precision;
      try
      {
        data.factorize_and_solve(type,
                                 matrix,
                                 rhs,
                                 solution,
                                 bordered,
                                 decoupled);
      }
      catch (const MumpsMemoryError &)
      {
        throw; // not the matrix (D177)
      }
      catch (const std::exception &error)
      {
        throw std::runtime_error(
          "the linear solver (" + type
          + ") failed; the stiffness matrix is probably singular (are "
            "rigid-body motions prevented by the boundary conditions?): "
          + error.what());
      }
    }


    namespace
    {
      // GMRES's control that also gives up early: when the mean reduction
      // per iteration so far, continued to the last allowed iteration,
      // would not reach the target (a factorisation is then cheaper than
      // the iterations left; D185).
      class ReuseControl : public SolverControl
      {
      public:
        ReuseControl(const unsigned int n, const double target)
            : SolverControl(n, target, false, false)
        {
        }

        State
        check(const unsigned int step, const double value) override
        {
          if (step == 0)
            initial = value;
          State state = SolverControl::check(step, value);
          if (state == iterate && step >= 2 && initial > 0.)
          {
            const double rate = std::pow(value / initial, 1. / step);
            if (value * std::pow(rate, max_steps() - step) > tolerance())
              state = failure;
          }
          return state;
        }

      private:
        double initial = 0.;
      };

      // The matrix of a solve: under mpirun each rank multiplies the rows it
      // owns, and the sum over the ranks is the product (D214).
      struct OwnedRowsOperator
      {
        const SparseMatrix<double> &matrix;
        const std::vector<bool>    &owned;

        void
        vmult(Vector<double> &dst, const Vector<double> &src) const
        {
          matrix.vmult(dst, src);
          if (owned.empty())
            return;
          for (types::global_dof_index i = 0; i < dst.size(); ++i)
            if (!owned[i])
              dst[i] = 0.;
          parallel::sum(dst.begin(), dst.size());
        }

        // |b - A x|, with r = b - A x.
        double
        residual(Vector<double>       &r,
                 const Vector<double> &x,
                 const Vector<double> &b) const
        {
          if (owned.empty())
            return matrix.residual(r, x, b);
          vmult(r, x);
          r.sadd(-1., 1., b);
          return r.l2_norm();
        }
      };

      // An earlier matrix's factors as the preconditioner of GMRES.
      struct KeptInverse
      {
        BorderedFactorization *factors;

        void
        vmult(Vector<double> &dst, const Vector<double> &src) const
        {
          factors->apply_kept_inverse(src, dst);
        }
      };
    } // namespace


    bool
    LinearSolver::solve_with_kept_factors(BorderedFactorization      &data,
                                          const SparseMatrix<double> &matrix,
                                          const Vector<double>       &rhs,
                                          Vector<double>             &solution)
    {
      solution.reinit(matrix.m());
      if (!gmres_with_factors(data, matrix, rhs, solution, forcing_term))
        return false;
      ++solve_statistics.reused_solves;
      return true;
    }


    bool
    LinearSolver::solve_in_single_precision(
      BorderedFactorization                      &data,
      const std::string                          &type,
      const SparseMatrix<double>                 &matrix,
      const Vector<double>                       &rhs,
      Vector<double>                             &solution,
      const std::vector<types::global_dof_index> &bordered,
      const std::vector<types::global_dof_index> &decoupled)
    {
      data.precision = FactorPrecision::single_precision;
      try
      {
        data.factorize_and_solve(type,
                                 matrix,
                                 rhs,
                                 solution,
                                 bordered,
                                 decoupled);
      }
      catch (const MumpsMemoryError &)
      {
        throw; // not the matrix (D177)
      }
      catch (const std::exception &)
      {
        // Singular in single precision: the double factorisation decides.
        ++solve_statistics.single_precision_fallbacks;
        return false;
      }
      ++solve_statistics.single_precision_factorizations;
      // The single-precision solve is GMRES' start.
      if (gmres_with_factors(data,
                             matrix,
                             rhs,
                             solution,
                             parameters.single_precision_tolerance))
        return true;
      ++solve_statistics.single_precision_fallbacks;
      return false;
    }


    bool
    LinearSolver::gmres_with_factors(BorderedFactorization      &data,
                                     const SparseMatrix<double> &matrix,
                                     const Vector<double>       &rhs,
                                     Vector<double>             &solution,
                                     const double relative_target)
    {
      // Right preconditioning: GMRES minimises the true residual |b - A x|,
      // which is also checked afterwards (D185).
      const double                target = relative_target * rhs.l2_norm();
      const unsigned int          budget = parameters.gmres_budget(matrix.m());
      ReuseControl                control(budget, target);
      SolverGMRES<Vector<double>> gmres(
        control,
        SolverGMRES<Vector<double>>::AdditionalData(budget + 2, true));
      const OwnedRowsOperator operator_A{matrix, data.owned_rows};
      bool                    converged = true;
      try
      {
        gmres.solve(operator_A, solution, rhs, KeptInverse{&data});
      }
      catch (const SolverControl::NoConvergence &)
      {
        converged = false;
      }
      catch (const std::exception &)
      {
        // The kept factors could not be applied: factorise afresh.
        converged = false;
      }
      solve_statistics.gmres_iterations += control.last_step();
      if (!converged)
        return false;
      Vector<double> residual(matrix.m());
      return operator_A.residual(residual, solution, rhs) <= 1.01 * target;
    }


    void
    LinearSolver::update_forcing_term(const double residual_norm)
    {
      // Eisenstat and Walker (1996), choice 2 with gamma = 0.9 and
      // alpha = 2, and its safeguard: a Newton step needs the linear
      // residual below forcing_term |F_k|, tighter as Newton converges,
      // but not below the smallest forcing term (D185).
      constexpr double gamma = 0.9;
      const double     limit = parameters.forcing_term;
      double           eta   = limit;
      if (previous_residual_norm > 0.)
      {
        const double ratio     = residual_norm / previous_residual_norm;
        eta                    = gamma * ratio * ratio;
        const double safeguard = gamma * forcing_term * forcing_term;
        if (safeguard > 0.1)
          eta = std::max(eta, safeguard);
      }
      forcing_term = std::clamp(eta, parameters.smallest_forcing_term, limit);

      previous_residual_norm = residual_norm;
    }
  } // namespace solver
} // namespace deepdraw
