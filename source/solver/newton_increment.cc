#include <algorithm>
#include <cmath>
#include <deepdraw/solver/newton_increment.h>
#include <limits>

namespace deepdraw
{
  namespace solver
  {
    std::string
    describe(const IncrementOutcome outcome)
    {
      switch (outcome)
      {
        case IncrementOutcome::converged:
          return "converged";
        case IncrementOutcome::too_many_iterations:
          return "too many Newton iterations";
        case IncrementOutcome::diverged:
          return "growing residual";
        case IncrementOutcome::stagnated:
          return "residual still above Newton/Stagnation residual";
        case IncrementOutcome::not_a_number:
          return "residual is not a number";
        case IncrementOutcome::inverted_element:
          return "inverted element (det F <= 0)";
        case IncrementOutcome::return_mapping_failed:
          return "local return mapping failed";
        case IncrementOutcome::enhanced_not_converged:
          return "enhanced parameters of an element did not converge";
        case IncrementOutcome::linear_solver_failed:
          return "linear solver failed";
      }
      return "unknown";
    }


    bool
    is_failed_point(const IncrementOutcome outcome)
    {
      return outcome == IncrementOutcome::inverted_element
             || outcome == IncrementOutcome::return_mapping_failed
             || outcome == IncrementOutcome::enhanced_not_converged;
    }


    NewtonIncrement::NewtonIncrement(const NewtonParameters &parameters)
        : parameters(parameters)
    {
    }


    const std::vector<double> &
    NewtonIncrement::force_residuals() const
    {
      return force_history;
    }


    const std::vector<double> &
    NewtonIncrement::contact_residuals() const
    {
      return contact_history;
    }


    namespace
    {
      // A step that inverts an element or breaks a return mapping is too
      // long whatever the merit says: it is halved up to this many times
      // before the increment is cut (doc/decisions.md D30).
      constexpr unsigned int failed_point_halvings = 5;
    } // namespace


    IncrementOutcome
    NewtonIncrement::run(NewtonSystem   &system,
                         Vector<double> &x,
                         const bool      start_assembled,
                         unsigned int   &iterations)
    {
      force_history.clear();
      contact_history.clear();
      Vector<double> correction(x.size());
      double         correction_norm   = 0.;
      double         smallest_residual = std::numeric_limits<double>::max();
      bool           assembled         = start_assembled;
      // An extrapolated start replaces the predictor solve (not counted).
      const unsigned int skipped_solves = start_assembled ? 1 : 0;

      for (unsigned int check = skipped_solves;; ++check)
      {
        iterations = check - skipped_solves;
        // Check 0 is the tangent predictor (reference Eq. 13): the
        // prescribed increment enters through the constraints.
        const bool predictor = check == 0;
        if (!assembled)
        {
          const IncrementOutcome status = system.assemble_at(x, predictor);
          if (status != IncrementOutcome::converged)
            return status;
        }
        assembled = false;

        if (check > 0)
        {
          const ResidualMeasures residuals = system.residual_measures();
          const double           relative_correction
            = system.relative_correction(x, correction_norm);
          force_history.push_back(residuals.force);
          contact_history.push_back(residuals.contact);
          system.record_iteration(iterations, residuals, relative_correction);
          if (!std::isfinite(residuals.force)
              || !std::isfinite(residuals.contact))
            return IncrementOutcome::not_a_number;
          // Right after the predictor (tangent or extrapolated) the whole
          // increment is "correction": there only the residuals decide.
          const bool only_predicted = check == 1;
          if (residuals.force <= parameters.force_tolerance
              && residuals.contact <= parameters.force_tolerance
              && residuals.tool_forces_met && residuals.enhanced_converged
              && iterations >= parameters.minimum_iterations
              && (only_predicted
                  || relative_correction <= parameters.correction_tolerance))
            return IncrementOutcome::converged;
          const double residual = std::max(residuals.force, residuals.contact);
          smallest_residual     = std::min(smallest_residual, residual);
          if (residual > parameters.divergence_ratio * smallest_residual)
            return IncrementOutcome::diverged;
          if (iterations >= parameters.maximum_iterations)
            return IncrementOutcome::too_many_iterations;
          if (parameters.stagnation_iterations > 0
              && iterations >= parameters.stagnation_iterations
              && residual > parameters.stagnation_residual)
            return IncrementOutcome::stagnated;
        }

        if (!system.solve_correction(correction, predictor))
          return IncrementOutcome::linear_solver_failed;
        correction_norm = system.correction_norm(correction);
        if (!std::isfinite(correction.l2_norm()))
          return IncrementOutcome::not_a_number;

        IncrementOutcome status;
        if (predictor)
          status = predictor_step(system, x, correction);
        else if (parameters.line_search_steps == 0)
        {
          x += correction;
          continue;
        }
        else
          status = line_search_step(system, x, correction, correction_norm);
        if (status != IncrementOutcome::converged)
          return status;
        assembled = true;
      }
    }


    IncrementOutcome
    NewtonIncrement::predictor_step(NewtonSystem         &system,
                                    Vector<double>       &x,
                                    const Vector<double> &correction) const
    {
      // The predictor extrapolates the last increment linearly; near tool
      // radii that can fold an element. Its free part is then halved;
      // prescribed displacements keep their full increment.
      const Vector<double> start = x;
      double               step  = 1.;
      for (unsigned int trial = 0;; ++trial)
      {
        x = start;
        for (types::global_dof_index i = 0; i < correction.size(); ++i)
          x[i] += (system.is_prescribed(i) ? 1. : step) * correction[i];
        const IncrementOutcome status = system.assemble_at(x, false);
        if (is_failed_point(status) && trial < failed_point_halvings)
        {
          step *= 0.5;
          continue;
        }
        return status;
      }
    }


    IncrementOutcome
    NewtonIncrement::line_search_step(NewtonSystem         &system,
                                      Vector<double>       &x,
                                      const Vector<double> &correction,
                                      double &correction_norm) const
    {
      // Backtracking on the merit: semismooth Newton on many contact nodes
      // can cycle between states; damping the step until the out-of-balance
      // force decreases breaks the cycle and leaves full steps (quadratic
      // convergence) near the solution (doc/decisions.md D19).
      const double         merit_now = system.merit();
      const Vector<double> start     = x;
      double               step      = 1.;
      for (unsigned int trial = 0, merit_trial = 0;; ++trial)
      {
        x = start;
        x.add(step, correction);
        const IncrementOutcome status = system.assemble_at(x, false);
        if (is_failed_point(status))
        {
          if (trial >= parameters.line_search_steps + failed_point_halvings)
            return status;
          step *= 0.5;
          continue;
        }
        if (status != IncrementOutcome::converged)
          return status;
        if (system.merit() <= (1. - 1e-4 * step) * merit_now
            || merit_trial >= parameters.line_search_steps)
          break;
        // The full step switches only a few contact pairs: the merit
        // rises because they switch, and a shorter step would switch them
        // back; take it whole (doc/decisions.md D91).
        const unsigned int changes = system.state_changes();
        if (merit_trial == 0 && step == 1.
            && parameters.full_step_state_changes > 0 && changes >= 1
            && changes <= parameters.full_step_state_changes)
          break;
        ++merit_trial;
        step *= 0.5;
      }
      correction_norm *= step;
      return IncrementOutcome::converged;
    }
  } // namespace solver
} // namespace deepdraw
