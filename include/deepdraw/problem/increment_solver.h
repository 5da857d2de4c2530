// One increment of the sheet model solved by Newton's method
// (solver::NewtonIncrement, doc/theory.md §5): its start (tangent or
// extrapolation predictor), the assembly of elements and contact, the
// correction's solve, and the convergence measures; also the
// re-equilibration at a fixed load after a mesh change (§8.3). Every
// convergence check is a row of newton.csv.
#ifndef deepdraw_problem_increment_solver_h
#define deepdraw_problem_increment_solver_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/problem/newton_log.h>
#include <deepdraw/problem/sheet_model.h>
#include <deepdraw/solver/newton_increment.h>
#include <string>

namespace deepdraw
{
  namespace problem
  {
    using namespace dealii;

    class IncrementSolver : private solver::NewtonSystem
    {
    public:
      using IncrementOutcome = solver::IncrementOutcome;

      IncrementSolver(SheetModel                     &model,
                      const solver::NewtonParameters &parameters);

      // newton.csv in directory (resume: appends).
      void
      open_log(const std::string &directory, bool resume);

      // From the committed state at old_load to new_load; iterations: the
      // Newton iterations it took.
      IncrementOutcome
      solve(double old_load, double new_load, unsigned int &iterations);
      // Newton at the committed load from du = 0; commits the equilibrium
      // if it converges.
      IncrementOutcome
      reequilibrate(unsigned int &iterations);
      // Commits the converged increment to the model.
      void
      commit();
      // After the model changed (stage, refinement, restart): the unknowns
      // of its committed state.
      void
      reset_unknowns();

      // The unknowns [du | lambda | z] of the last attempt.
      const Vector<double> &
      unknowns() const;
      const NewtonProgress &
      progress() const;
      // Before an increment's first attempt: its times back to zero (they
      // include the failed attempts).
      void
      start_timing();

      // For tests: the prescribed increments and tool positions of the
      // increment [old_load, new_load], as an increment sets them.
      void
      prepare_increment(double old_load, double new_load);
      // The residual r(x) of all equations for the Newton unknowns x,
      // without constraints; with tangent != nullptr also dr/dx. False if
      // a point failed.
      bool
      evaluate_residual(const Vector<double> &unknowns,
                        Vector<double>       &residual,
                        FullMatrix<double>   *tangent);
      // Residual and tangent without constraints, as one iteration does.
      bool
      assemble_system(const Vector<double> &unknowns);

    private:
      // An attempt from old_load to new_load begins: du = 0, contact forces
      // and tool positions converged, the element-internal unknowns the
      // last increment's times enhanced_ratio.
      void
      start_attempt(double old_load, double new_load, double enhanced_ratio);
      void
      start_from_converged_state();
      IncrementOutcome
      assemble(const Vector<double>            &unknowns,
               const AffineConstraints<double> &constraints,
               bool                             with_matrix);

      // solver::NewtonSystem: the iterate is newton_unknowns.
      IncrementOutcome
      assemble_at(const Vector<double> &x, bool predictor) override;
      bool
      solve_correction(Vector<double> &correction, bool predictor) override;
      bool
      is_prescribed(types::global_dof_index i) const override;
      solver::ResidualMeasures
      residual_measures() const override;
      double
      merit() const override;
      unsigned int
      state_changes() const override;
      double
      correction_norm(const Vector<double> &correction) const override;
      double
      relative_correction(const Vector<double> &x,
                          double                correction_norm) const override;
      void
      record_iteration(unsigned int                    iterations,
                       const solver::ResidualMeasures &residuals,
                       double relative_correction) override;

      SheetModel                     &model;
      const solver::NewtonParameters &parameters;
      NewtonLog                       log;
      Vector<double>                  newton_unknowns;
      double                          start_load  = 0.;
      double                          target_load = 0.;
      NewtonProgress                  newton_progress;
    };
  } // namespace problem
} // namespace deepdraw

#endif
