#include <cmath>
#include <deepdraw/material/hardening_law.h>

namespace deepdraw
{
  namespace material
  {
    HardeningLaw::HardeningLaw(const MaterialParameters &parameters)
        : swift_coefficient(parameters.swift_coefficient)
        , swift_prestrain(parameters.swift_prestrain)
        , swift_exponent(parameters.swift_exponent)
    {
    }


    void
    HardeningLaw::evaluate(const double epbar, double &Y, double &dY) const
    {
      // The arithmetic of the reference model, unchanged.
      const double strain = swift_prestrain + epbar;
      Y  = swift_coefficient * std::pow(strain, swift_exponent);
      dY = swift_exponent * Y / strain;
    }


    double
    HardeningLaw::yield_stress(const double epbar) const
    {
      double Y, dY;
      evaluate(epbar, Y, dY);
      return Y;
    }


    double
    HardeningLaw::hardening_modulus(const double epbar) const
    {
      double Y, dY;
      evaluate(epbar, Y, dY);
      return dY;
    }
  } // namespace material
} // namespace deepdraw
