#include <cmath>
#include <deepdraw/contact/contact_parameters.h>
#include <deepdraw/io/input_error.h>
#include <string>

namespace deepdraw
{
  namespace contact
  {
    namespace
    {
      // Patterns::Double() lets any number through, so that the range check
      // below, not ParameterHandler, reports it as an InputError.
      double
      get_checked(dealii::ParameterHandler &prm,
                  const std::string        &entry,
                  const bool                allow_zero,
                  const double              maximum,
                  const std::string        &allowed)
      {
        const double value = prm.get_double(entry);
        if (!std::isfinite(value) || value < 0. || (!allow_zero && value == 0.)
            || value > maximum)
          throw InputError("Contact/" + entry + " = " + prm.get(entry)
                           + " is not allowed: " + allowed + ".");
        return value;
      }
    } // namespace


    void
    ContactParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Friction coefficient",
                        "0.162",
                        dealii::Patterns::Double(),
                        "Coulomb friction coefficient between the sheet and "
                        "all tools; 0 to 10 (0: frictionless).");
      prm.declare_entry(
        "Augmentation parameter",
        "0",
        dealii::Patterns::Double(),
        "Augmentation parameter r of the Alart-Curnier law, in N/mm; 0 to "
        "1e15. 0 selects the automatic value, one for all contact "
        "pairs: r = (Augmentation scaling) x E x h, h = sqrt(dx dy) the "
        "in-plane size of the blank's elements. The converged solution does "
        "not depend on r, only the Newton convergence does.");
      prm.declare_entry("Augmentation scaling",
                        "1",
                        dealii::Patterns::Double(),
                        "Factor on the automatic augmentation parameter; "
                        "0 < value <= 1e6. E x (element size) is the in-plane "
                        "stiffness of a node; a thin sheet pressed by a tool "
                        "resists by bending, about E t^3 / h^2, i.e. 0.01-0.02 "
                        "for the square cup (t = 0.81, h = 3 mm), where 0.01 "
                        "needed the fewest Newton iterations (D34).");
      prm.declare_entry(
        "Linearisation",
        "full",
        dealii::Patterns::Selection("full|frozen normal"),
        "Derivative of the gap in the Newton matrix: 'full' includes the "
        "motion of the closest point and the rotation of the tool normal "
        "(curvature terms, exact on radii); 'frozen normal' holds both "
        "fixed.");
    }


    void
    ContactParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      // Upper bounds (D50): a friction coefficient of 10 is far beyond any
      // tool and sheet; the augmentation only scales the contact rows.
      friction_coefficient = get_checked(prm,
                                         "Friction coefficient",
                                         true,
                                         10.,
                                         "a number >= 0 and <= 10");
      augmentation_parameter
        = get_checked(prm,
                      "Augmentation parameter",
                      true,
                      1e15,
                      "a number >= 0 and <= 1e15 N/mm (0: automatic)");
      augmentation_scaling = get_checked(prm,
                                         "Augmentation scaling",
                                         false,
                                         1e6,
                                         "a number > 0 and <= 1e6");
      const std::string l  = prm.get("Linearisation");
      if (l == "full")
        linearisation = Linearisation::full;
      else if (l == "frozen normal")
        linearisation = Linearisation::frozen_normal;
      else
        throw InputError("Contact/Linearisation = " + l
                         + " is not allowed: full or frozen normal.");
    }


    double
    ContactParameters::augmentation(const double youngs_modulus,
                                    const double element_size) const
    {
      if (augmentation_parameter > 0.)
        return augmentation_parameter;
      return augmentation_scaling * youngs_modulus * element_size;
    }
  } // namespace contact
} // namespace deepdraw
