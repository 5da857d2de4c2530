// The Keeler-Brazier forming-limit curve of low-carbon steels from the
// hardening exponent n and the sheet thickness t (doc/theory_formability.md
// §2.2, D132): FLC0 = (23.3 + 14.13 t) n / 0.21 in % engineering major
// strain (t in mm), the left side a line of constant thickness strain
// eps1 + eps2 = eps1_0 in true strains, the right side e1 = e1_0 + 0.6 e2
// in engineering strains.
#ifndef deepdraw_formability_keeler_brazier_flc_h
#define deepdraw_formability_keeler_brazier_flc_h

#include <deepdraw/formability/forming_limit_curve.h>

namespace deepdraw
{
  namespace formability
  {
    class KeelerBrazierFlc : public FormingLimitCurve
    {
    public:
      // The range of the correlation: 0 < n <= 0.21 and 0 < t <= 3 mm;
      // outside it, InputError naming n_source and t_source (the entries or
      // Material/Geometry parameters the values came from).
      KeelerBrazierFlc(double             n,
                       double             thickness,
                       const std::string &n_source,
                       const std::string &thickness_source);

      // FLC0 in % engineering major strain.
      static double
      flc0_percent(double n, double thickness);

      double
      limit_major_strain(double minor_strain) const override;

      // Samples from the uniaxial path of an isotropic sheet on the left
      // (eps2 = -eps1_0) to a minor engineering strain of 20 % on the right,
      // the range the correlation was drawn from.
      std::vector<FlcPoint>
      points() const override;

      std::string
      description() const override;

    private:
      double n, thickness;
      // ln(1 + FLC0 / 100).
      double eps1_0;
    };
  } // namespace formability
} // namespace deepdraw

#endif
