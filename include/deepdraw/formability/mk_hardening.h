// The isotropic hardening law of subsection Material as the
// Marciniak-Kuczynski analysis needs it (doc/theory_formability.md §4.6):
// Y(epbar) of material::HardeningLaw (Swift, Voce or tabulated) and its
// inverse epbar(Y), the strain at which the law reaches a stress. The
// inverse is Swift's closed form for the Swift law (the arithmetic of the
// analysis before the other laws existed, D170) and a safeguarded
// Newton-bisection on the monotone law otherwise. A law that saturates (Voce
// at A, a table whose last segment is flat) has no strain for a stress at
// or above its saturation: the inverse is +infinity there.
#ifndef deepdraw_formability_mk_hardening_h
#define deepdraw_formability_mk_hardening_h

#include <deepdraw/material/hardening_law.h>
#include <deepdraw/material/material_parameters.h>
#include <string>

namespace deepdraw
{
  namespace formability
  {
    class MkHardening
    {
    public:
      // Validates the material parameters (InputError).
      explicit MkHardening(const material::MaterialParameters &parameters);

      double
      yield_stress(double equivalent_plastic_strain) const;

      // The least epbar >= 0 with Y(epbar) >= stress: 0 at or below Y(0),
      // +infinity at or above saturation_stress().
      double
      equivalent_strain(double stress) const;

      // The same by the safeguarded Newton-bisection, whatever the law (the
      // Swift law's closed form is checked against it).
      double
      solve_equivalent_strain(double stress) const;

      // sup Y: A for Voce, the last stress of a table whose last segment is
      // flat, +infinity otherwise.
      double
      saturation_stress() const;

      // "" if the law hardens, else why a limit strain cannot be computed
      // (a perfectly plastic law has the limit strain zero), naming the
      // parameter: "Material/Swift exponent is 0: ...".
      std::string
      without_hardening() const;

      // A strain of the order of Hill's localized-necking strain, to order
      // the groove angles (D137): the Swift exponent n, else the uniaxial
      // Considere strain (Y' = Y) of the law.
      double
      necking_strain() const;

      // "Swift n = 0.3593", "Voce A = 413 MPa, B = 280.8 MPa, C = 6.5",
      // "tabulated (7 points)", for the curve's description.
      std::string
      description() const;

      // Where a saturation reached by the analysis comes from
      // ("Material/Voce A = 413 MPa").
      std::string
      saturation_source() const;

    private:
      material::MaterialParameters parameters;
      material::HardeningLaw       law;
    };
  } // namespace formability
} // namespace deepdraw

#endif
