#include <deepdraw/solver/newton_parameters.h>

namespace deepdraw
{
  namespace solver
  {
    void
    NewtonParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Newton");
      prm.declare_entry("Maximum iterations",
                        "15",
                        Patterns::Integer(1),
                        "Newton iterations allowed per increment before it "
                        "is cut back.");
      prm.declare_entry("Force tolerance",
                        "1e-6",
                        Patterns::Double(0.),
                        "Converged when the out-of-balance force norm over "
                        "the free degrees of freedom, divided by the norm of "
                        "the internal force vector (reactions included), is "
                        "below this ...");
      prm.declare_entry("Correction tolerance",
                        "1e-6",
                        Patterns::Double(0.),
                        "... and the last Newton correction, divided by the "
                        "displacement increment, is below this.");
      prm.declare_entry("Divergence ratio",
                        "1e4",
                        Patterns::Double(1.),
                        "An increment counts as diverging when its residual "
                        "exceeds the smallest residual of the increment by "
                        "this factor.");
      prm.leave_subsection();
    }



    void
    NewtonParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Newton");
      maximum_iterations   = prm.get_integer("Maximum iterations");
      force_tolerance      = prm.get_double("Force tolerance");
      correction_tolerance = prm.get_double("Correction tolerance");
      divergence_ratio     = prm.get_double("Divergence ratio");
      prm.leave_subsection();
    }
  } // namespace solver
} // namespace deepdraw
