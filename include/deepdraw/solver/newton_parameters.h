// Controls of the global Newton-Raphson loop (doc/theory.md §5).
#ifndef deepdraw_solver_newton_parameters_h
#define deepdraw_solver_newton_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <string>

namespace deepdraw
{
  namespace solver
  {
    using namespace dealii;

    struct NewtonParameters
    {
      unsigned int maximum_iterations = 15;
      // Newton iterations (corrections after the predictor) an increment
      // needs before it may converge: 1 keeps an extrapolated start from
      // being accepted as it stands (doc/decisions.md D208).
      unsigned int minimum_iterations   = 0;
      double       force_tolerance      = 1e-6;
      double       correction_tolerance = 1e-6;
      // Residual growth over the smallest residual seen in the increment
      // that counts as divergence.
      double divergence_ratio = 1e4;
      // Halvings of the Newton step allowed by the line search (0: none).
      unsigned int line_search_steps = 4;
      // A step whose full trial changes the contact state of at least one
      // and at most this many pairs is taken whole, without backtracking
      // (0: always backtrack; doc/decisions.md D91).
      unsigned int full_step_state_changes = 0;
      // An increment whose relative residual is still above
      // stagnation_residual after stagnation_iterations iterations is cut
      // back at once (0: never).
      unsigned int stagnation_iterations = 8;
      double       stagnation_residual   = 0.1;
      // First guess of an increment: "tangent" (the tangent predictor of
      // reference Eq. 13) or "extrapolation" (the last converged increment
      // scaled to the new one; no linear solve).
      std::string predictor = "tangent";
      // Error of the force of a force-controlled tool relative to the
      // prescribed force that convergence allows in addition (0: none).
      double tool_force_tolerance = 0.;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      // Process/Stage N/Newton (D208; solver/stage_overrides.h): Minimum
      // and Maximum iterations, Force and Correction tolerance, as
      // IncrementControlParameters does for Load stepping.
      static void
      declare_overrides(ParameterHandler &prm);
      void
      parse_overrides(ParameterHandler &prm, const std::string &prefix);
      static std::string
      first_override(ParameterHandler &prm);

    private:
      // Throws InputError (prefix + the parameter) for values out of range.
      void
      check(const std::string &prefix) const;
    };
  } // namespace solver
} // namespace deepdraw

#endif
