// The Newton-Raphson iterations of one load increment (doc/theory.md §5):
// predictor solve, corrections, backtracking line search, halving of steps
// that break a point, and the decision to stop (converged, or why not, so
// that the caller can cut the increment back). It works on NewtonSystem, an
// interface to the assembled problem, not on the forming problem itself.
#ifndef deepdraw_solver_newton_increment_h
#define deepdraw_solver_newton_increment_h

#include <deal.II/base/types.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/solver/newton_parameters.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace solver
  {
    using namespace dealii;

    enum class IncrementOutcome
    {
      converged,
      too_many_iterations,
      diverged,
      stagnated,
      not_a_number,
      inverted_element,
      return_mapping_failed,
      enhanced_not_converged,
      linear_solver_failed
    };

    // Why an attempt stopped, in words for the log.
    std::string
    describe(IncrementOutcome outcome);

    // An inverted element or a failed local solve: the step was too long.
    bool
    is_failed_point(IncrementOutcome outcome);

    // Relative convergence measures of the last assembly (doc/theory.md
    // §5.2).
    struct ResidualMeasures
    {
      double force   = 0.; // free out-of-balance forces / force scale
      double contact = 0.; // contact equations / force scale
      // Force-controlled tools meet their force to the tolerance.
      bool tool_forces_met = true;
      // Every element's enhanced parameters meet their tolerance (D189).
      bool enhanced_converged = true;
    };

    // What one increment needs of the discretised problem. The unknowns x
    // are the Newton unknowns of the increment; "predictor" selects the
    // constraints of the first solve (prescribed increments applied),
    // otherwise homogeneous constraints.
    class NewtonSystem
    {
    public:
      virtual ~NewtonSystem() = default;

      // Residual and tangent at x.
      virtual IncrementOutcome
      assemble_at(const Vector<double> &x, bool predictor)
        = 0;
      // The correction of the last assembly (constraints applied); false
      // if the linear solver failed (it has said why).
      virtual bool
      solve_correction(Vector<double> &correction, bool predictor)
        = 0;
      // Whether unknown i carries a prescribed increment (the predictor's
      // step halving keeps those whole).
      virtual bool
      is_prescribed(types::global_dof_index i) const = 0;
      // Of the last assembly.
      virtual ResidualMeasures
      residual_measures() const = 0;
      // Merit of the last assembly for the line search (N).
      virtual double
      merit() const = 0;
      // Contact pairs whose state (open / stick / slip) the last assembly
      // changed; a system without such states has none (D91).
      virtual unsigned int
      state_changes() const
      {
        return 0;
      }
      // Norm of the displacement part of a correction (mm), and that
      // norm relative to the displacement so far (at x).
      virtual double
      correction_norm(const Vector<double> &correction) const = 0;
      virtual double
      relative_correction(const Vector<double> &x,
                          double                correction_norm) const = 0;
      // Once per convergence check (iterations = linear solves so far).
      virtual void
      record_iteration(unsigned int            iterations,
                       const ResidualMeasures &residuals,
                       double                  relative_correction)
        = 0;
    };

    class NewtonIncrement
    {
    public:
      explicit NewtonIncrement(const NewtonParameters &parameters);

      // Iterates from x (in: the start, out: the last iterate). With
      // start_assembled the system was assembled at x with homogeneous
      // constraints (an extrapolated start): the predictor solve is
      // skipped and not counted. iterations: linear solves.
      IncrementOutcome
      run(NewtonSystem   &system,
          Vector<double> &x,
          bool            start_assembled,
          unsigned int   &iterations);

      // Relative residuals at each check of the last run.
      const std::vector<double> &
      force_residuals() const;
      const std::vector<double> &
      contact_residuals() const;

    private:
      // The step x + s correction (the prescribed part of a predictor
      // correction always whole), halved while it breaks a point.
      IncrementOutcome
      predictor_step(NewtonSystem         &system,
                     Vector<double>       &x,
                     const Vector<double> &correction) const;
      // Backtracking on the merit; scales correction_norm by the step.
      IncrementOutcome
      line_search_step(NewtonSystem         &system,
                       Vector<double>       &x,
                       const Vector<double> &correction,
                       double               &correction_norm) const;

      NewtonParameters    parameters;
      std::vector<double> force_history;
      std::vector<double> contact_history;
    };
  } // namespace solver
} // namespace deepdraw

#endif
