// Isotropic hardening: the yield stress Y(epbar) of the rolling-direction
// uniaxial curve and its slope (doc/theory_material.md §1.3). Swift
// Y = C (eps0 + epbar)^n, Voce Y = A - B exp(-C epbar), or a piecewise
// linear table of (epbar, Y) pairs extrapolated with the slope of its last
// segment. Immutable after construction, no heap allocation when evaluated.
#ifndef deepdraw_material_hardening_law_h
#define deepdraw_material_hardening_law_h

#include <deepdraw/material/material_parameters.h>
#include <vector>

namespace deepdraw
{
  namespace material
  {
    class HardeningLaw
    {
    public:
      // The parameters must have been validated.
      explicit HardeningLaw(const MaterialParameters &parameters);

      // Y and dY/d epbar at epbar (one pow() or exp() at most).
      void
      evaluate(const double epbar, double &Y, double &dY) const;

      double
      yield_stress(const double epbar) const;

      double
      hardening_modulus(const double epbar) const;

    private:
      HardeningLawType type;

      double swift_coefficient, swift_prestrain, swift_exponent;
      double voce_A, voce_B, voce_C;

      // Tabulated: strictly increasing strains from 0, stresses and the
      // slope of the segment that starts at each point (the last one
      // repeats the slope of the last segment, 0 for a single point).
      std::vector<double> table_strains, table_stresses, table_slopes;
    };
  } // namespace material
} // namespace deepdraw

#endif
