// LinearSolver: each Newton system solved by a fresh or kept factorisation
// (double or single precision, GMRES where factors are kept, D185, D226) or
// by AMG; its parameters are in linear_solver_parameters.cc.
#include <algorithm>
#include <cmath>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deepdraw/parallel/ranks.h>
#include <deepdraw/solver/bordered_amg_solver.h>
#include <deepdraw/solver/bordered_factorization.h>
#include <deepdraw/solver/linear_solver.h>
#include <stdexcept>

namespace deepdraw
{
  namespace solver
  {
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
