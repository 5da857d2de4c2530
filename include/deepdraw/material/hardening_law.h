// Isotropic hardening: the yield stress Y(epbar) of the rolling-direction
// uniaxial curve and its slope (doc/theory_material.md): Swift
// Y = C (eps0 + epbar)^n. Immutable after construction, no heap allocation
// when evaluated.
#ifndef deepdraw_material_hardening_law_h
#define deepdraw_material_hardening_law_h

#include <deepdraw/material/material_parameters.h>
namespace deepdraw
{
  namespace material
  {
    class HardeningLaw
    {
    public:
      // The parameters must have been validated.
      explicit HardeningLaw(const MaterialParameters &parameters);

      // Y and dY/d epbar at epbar (one pow()).
      void
      evaluate(const double epbar, double &Y, double &dY) const;

      double
      yield_stress(const double epbar) const;

      double
      hardening_modulus(const double epbar) const;

    private:
      double swift_coefficient, swift_prestrain, swift_exponent;
    };
  } // namespace material
} // namespace deepdraw

#endif
