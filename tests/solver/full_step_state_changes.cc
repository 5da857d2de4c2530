// Newton/Full step state changes (doc/decisions.md D91) on a problem with a
// known solution, independent of the forming problem: one node on a
// softening spring s(u) = k a tanh(u / a), pushed by a force f towards a
// rigid obstacle at distance g0, with the normal Alart-Curnier law
// (doc/theory_contact.md §2, reference Eq. 12) and the unknowns (u, lambda):
//
//   R_u      = s(u) + P - f,   P = max(0, lambda - r (g0 - u)),
//   R_lambda = (lambda - P) / r.
//
// f exceeds s(g0), so the solution is in contact: u = g0 exactly and
// lambda = f - s(g0). From u = 0 the predictor stays short of the obstacle
// and the next Newton step (the spring softens) passes it: the contact
// closes and the merit rises by r times the penetration. The backtracking
// line search then halves the step back to the open side, again in each
// iteration, and approaches the obstacle from the open side; with the rule,
// the step that closes the contact (one state change) is taken whole and
// the closed state, linear in the gap, gives u = g0 at the next step.
// Checked: both reach the analytic (u, lambda) to 1e-12 (the residual
// tolerance: u = g0 is exact in the closed state and dR_u/dlambda = 1, so
// an iterate that meets it is that close; measured 0 and 3e-17); with the
// rule in at most 5 iterations (4 measured) and in fewer than without it
// (6 measured); the rule leaves a problem without contact states
// (atan(x) = 0 from x = 2, where plain Newton diverges) to the line search.
#include "test_utilities.h"

#include <array>
#include <cmath>
#include <deal.II/lac/vector.h>
#include <deepdraw/solver/newton_increment.h>

using namespace dealii;
using namespace deepdraw;
using solver::IncrementOutcome;

namespace
{
  constexpr double k  = 1.;  // N/mm, spring stiffness at u = 0
  constexpr double a  = 1.;  // mm, softening length
  constexpr double f  = 0.9; // N
  constexpr double g0 = 1.2; // mm, initial gap
  constexpr double r  = 10.; // N/mm, augmentation

  // contact = true: the node-obstacle problem above; false: atan(u) = 0
  // (lambda stays 0, no states).
  struct ObstacleSystem : public solver::NewtonSystem
  {
    explicit ObstacleSystem(const bool contact)
        : contact(contact)
    {
    }

    IncrementOutcome
    assemble_at(const Vector<double> &x, bool) override
    {
      const double u = x[0], lambda = x[1];
      if (!contact)
      {
        residual = {{std::atan(u), lambda}};
        jacobian = {{1. / (1. + u * u), 0., 0., 1.}};
        return IncrementOutcome::converged;
      }
      const double augmented  = lambda - r * (g0 - u);
      const bool   now_closed = augmented > 0.;
      changes                 = now_closed != closed ? 1 : 0;
      closed                  = now_closed;
      const double t          = std::tanh(u / a);
      const double P          = closed ? augmented : 0.;
      residual                = {{k * a * t + P - f, (lambda - P) / r}};
      // d/du and d/dlambda of both rows.
      jacobian = {{k * (1. - t * t) + (closed ? r : 0.),
                   closed ? 1. : 0.,
                   closed ? -1. : 0.,
                   closed ? 0. : 1. / r}};
      return IncrementOutcome::converged;
    }

    bool
    solve_correction(Vector<double> &correction, bool) override
    {
      const double det = jacobian[0] * jacobian[3] - jacobian[1] * jacobian[2];
      correction[0]
        = -(jacobian[3] * residual[0] - jacobian[1] * residual[1]) / det;
      correction[1]
        = -(-jacobian[2] * residual[0] + jacobian[0] * residual[1]) / det;
      return true;
    }

    bool
    is_prescribed(types::global_dof_index) const override
    {
      return false;
    }

    double
    merit() const override
    {
      // r R_lambda is a force, as in ContactCoupling::residual_norm.
      return std::hypot(residual[0], r * residual[1]);
    }

    solver::ResidualMeasures
    residual_measures() const override
    {
      solver::ResidualMeasures measures;
      measures.force   = std::abs(residual[0]);
      measures.contact = std::abs(r * residual[1]);
      return measures;
    }

    unsigned int
    state_changes() const override
    {
      return changes;
    }

    double
    correction_norm(const Vector<double> &correction) const override
    {
      return std::abs(correction[0]);
    }

    double
    relative_correction(const Vector<double> &x,
                        const double          norm) const override
    {
      return x[0] != 0. ? norm / std::abs(x[0]) : 0.;
    }

    void
    record_iteration(unsigned int,
                     const solver::ResidualMeasures &,
                     double) override
    {
    }

    bool                  contact;
    bool                  closed  = false;
    unsigned int          changes = 0;
    std::array<double, 2> residual{};
    std::array<double, 4> jacobian{};
  };


  solver::NewtonParameters
  parameters(const unsigned int full_step_state_changes)
  {
    solver::NewtonParameters parameters;
    parameters.force_tolerance         = 1e-12;
    parameters.correction_tolerance    = 1e-12;
    parameters.maximum_iterations      = 40;
    parameters.stagnation_iterations   = 0;
    parameters.line_search_steps       = 2; // as prm/square_cup.prm
    parameters.full_step_state_changes = full_step_state_changes;
    return parameters;
  }


  unsigned int
  solve_obstacle(const unsigned int full_step_state_changes)
  {
    std::cout << "obstacle, Full step state changes = "
              << full_step_state_changes << std::endl;
    ObstacleSystem         system(true);
    Vector<double>         x(2);
    unsigned int           iterations = 0;
    const IncrementOutcome outcome
      = solver::NewtonIncrement(parameters(full_step_state_changes))
          .run(system, x, false, iterations);
    deepdraw_test::check_true("converged (" + solver::describe(outcome)
                                + ") in " + std::to_string(iterations),
                              outcome == IncrementOutcome::converged);
    deepdraw_test::check_close("u = g0", x[0], g0, 1e-12);
    deepdraw_test::check_close("lambda = f - s(g0)",
                               x[1],
                               f - k * a * std::tanh(g0 / a),
                               1e-12);
    return iterations;
  }
} // namespace


int
main()
{
  const unsigned int backtracking = solve_obstacle(0);
  const unsigned int full_step    = solve_obstacle(1);
  deepdraw_test::check_true("with the rule " + std::to_string(full_step)
                              + " <= 5 iterations",
                            full_step <= 5);
  deepdraw_test::check_true("fewer than backtracking alone ("
                              + std::to_string(backtracking) + ")",
                            full_step < backtracking);

  {
    std::cout << "atan(x) = 0 from x = 2, no contact states" << std::endl;
    ObstacleSystem system(false);
    Vector<double> x(2);
    x[0]                              = 2.;
    unsigned int           iterations = 0;
    const IncrementOutcome outcome    = solver::NewtonIncrement(parameters(1))
                                       .run(system, x, false, iterations);
    deepdraw_test::check_true("converged by the line search ("
                                + solver::describe(outcome) + ")",
                              outcome == IncrementOutcome::converged);
    deepdraw_test::check_close("x = 0", x[0], 0., 1e-12);
  }
  return deepdraw_test::summary();
}
