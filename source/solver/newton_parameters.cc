#include <deal.II/base/utilities.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/solver/newton_parameters.h>
#include <deepdraw/solver/stage_overrides.h>
#include <string>
#include <utility>
#include <vector>

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
                        Patterns::Integer(1, 1000),
                        "Newton iterations allowed per increment before it "
                        "is cut back (1 to 1000).");
      prm.declare_entry(
        "Minimum iterations",
        "0",
        Patterns::Integer(0, 1000),
        "Newton iterations an increment must take before it may count as "
        "converged (0 to Maximum iterations). 0: an increment whose "
        "predictor already meets the tolerances ends there. 1: an increment "
        "started by the extrapolation predictor takes at least one Newton "
        "correction, so that the error an accepted state leaves within the "
        "tolerances does not build up from increment to increment "
        "(doc/decisions.md D208). The tangent predictor's solve counts as "
        "the first iteration.");
      prm.declare_entry(
        "Force tolerance",
        "1e-6",
        Patterns::Double(0., 1.),
        "0 < value < 1. The increment has converged when the out-of-balance "
        "force norm over the free displacement unknowns, and "
        "that of the contact equations (r F_sup and the tool "
        "equations), each divided by the norm of the "
        "internal force vector (reactions included), are "
        "below this, and the correction criterion holds.");
      prm.declare_entry(
        "Correction tolerance",
        "1e-6",
        Patterns::Double(0., 1.),
        "0 < value < 1. The last Newton correction of the displacements, "
        "divided by the larger of the increment and the "
        "total displacement, must be below this for "
        "convergence (from the second iteration after the "
        "predictor on).");
      prm.declare_entry("Divergence ratio",
                        "1e4",
                        Patterns::Double(1., 1e100),
                        "An increment counts as diverging when its residual "
                        "exceeds the smallest residual of the increment by "
                        "this factor (1 to 1e100).");
      prm.declare_entry("Line search steps",
                        "4",
                        Patterns::Integer(0, 20),
                        "Halvings of a Newton step allowed when it does not "
                        "reduce the out-of-balance forces (0 switches the "
                        "line search off).");
      prm.declare_entry(
        "Full step state changes",
        "0",
        Patterns::Integer(0, 1000000),
        "A Newton step whose full length changes the contact state (open, "
        "stick, slip) of at least one and at most this many contact pairs is "
        "taken whole even if it does not reduce the out-of-balance forces: "
        "the few pairs it switches are the ones the semismooth Newton is "
        "settling, and halving the step only keeps them switching back "
        "(doc/decisions.md D91). 0: the line search always backtracks.");
      prm.declare_entry("Stagnation iterations",
                        "8",
                        Patterns::Integer(0, 1000),
                        "An increment whose relative residual is still above "
                        "Stagnation residual after this many iterations is "
                        "cut back without using up Maximum iterations "
                        "(0: never). In the square cup, such increments "
                        "never converged but cost half the run time.");
      prm.declare_entry("Stagnation residual",
                        "0.1",
                        Patterns::Double(0., 1e100),
                        "See Stagnation iterations (relative residual, as "
                        "Force tolerance; 0 to 1e100).");
      prm.declare_entry(
        "Predictor",
        "tangent",
        Patterns::Selection("tangent|extrapolation"),
        "First guess of each increment. 'tangent': the tangent predictor "
        "(one linear solve with the prescribed increments, reference "
        "Eq. 13). 'extrapolation': the last converged increment of the "
        "displacements, contact forces and tool positions scaled to the new "
        "load increment, no linear solve; the tangent predictor is used for "
        "the first increment and when the extrapolated state inverts an "
        "element or breaks a return mapping.");
      prm.declare_entry(
        "Tool force tolerance",
        "0",
        Patterns::Double(0., 1.),
        "0 <= value < 1. If > 0, convergence also requires the force of every "
        "force-controlled tool to equal its prescribed force to this "
        "relative error (a zero prescribed force: relative to the force "
        "scale of Force tolerance). The tool equations are part of the contact "
        "residual of Force tolerance anyway; this bounds them separately "
        "when Force tolerance is loose (0: no separate bound).");
      prm.leave_subsection();
    }


    void
    NewtonParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Newton");
      maximum_iterations      = prm.get_integer("Maximum iterations");
      minimum_iterations      = prm.get_integer("Minimum iterations");
      force_tolerance         = prm.get_double("Force tolerance");
      correction_tolerance    = prm.get_double("Correction tolerance");
      divergence_ratio        = prm.get_double("Divergence ratio");
      line_search_steps       = prm.get_integer("Line search steps");
      full_step_state_changes = prm.get_integer("Full step state changes");
      stagnation_iterations   = prm.get_integer("Stagnation iterations");
      stagnation_residual     = prm.get_double("Stagnation residual");
      predictor               = prm.get("Predictor");
      tool_force_tolerance    = prm.get_double("Tool force tolerance");
      prm.leave_subsection();
      check("Newton/");
    }


    namespace
    {
      // The entries a stage may set for itself (D208), with their ranges.
      const char *const stage_note
        = "Allowed as there; a release by tool retraction may need its own "
          "(doc/decisions.md D208).";
      const std::vector<OverridableEntry> overrides
        = {{"Minimum iterations", 0, 1000, true, stage_note},
           {"Maximum iterations", 1, 1000, true, stage_note},
           {"Force tolerance", 0., 1., false, stage_note},
           {"Correction tolerance", 0., 1., false, stage_note}};
    } // namespace


    void
    NewtonParameters::declare_overrides(ParameterHandler &prm)
    {
      solver::declare_overrides(prm, "Newton", overrides);
    }


    void
    NewtonParameters::parse_overrides(ParameterHandler  &prm,
                                      const std::string &prefix)
    {
      solver::parse_overrides(
        prm,
        "Newton",
        overrides,
        prefix,
        [this](const std::string &name, const std::string &value)
        {
          if (name == "Minimum iterations")
            minimum_iterations = Utilities::string_to_int(value);
          else if (name == "Maximum iterations")
            maximum_iterations = Utilities::string_to_int(value);
          else if (name == "Force tolerance")
            force_tolerance = Utilities::string_to_double(value);
          else
            correction_tolerance = Utilities::string_to_double(value);
        });
      check(prefix + "Newton/");
    }


    std::string
    NewtonParameters::first_override(ParameterHandler &prm)
    {
      return solver::first_override(prm, "Newton", overrides);
    }


    void
    NewtonParameters::check(const std::string &prefix) const
    {
      if (minimum_iterations > maximum_iterations)
        throw InputError(prefix + "Minimum iterations = "
                         + std::to_string(minimum_iterations)
                         + " exceeds Maximum iterations = "
                         + std::to_string(maximum_iterations)
                         + ": allowed are 0 to Maximum iterations");
      // A tolerance of 0 can never be met (every increment would be cut back
      // to Minimum increment), 1 accepts anything (D50).
      const std::pair<const char *, double> tolerances[]
        = {{"Force tolerance", force_tolerance},
           {"Correction tolerance", correction_tolerance},
           {"Tool force tolerance", tool_force_tolerance}};
      for (const auto &[name, value] : tolerances)
        if (!(value < 1.) || (value == 0. && name[0] != 'T'))
          throw InputError(
            prefix + std::string(name) + " = " + std::to_string(value)
            + " is not allowed: "
            + (name[0] == 'T' ? "0 <= value < 1" : "0 < value < 1"));
    }
  } // namespace solver
} // namespace deepdraw
