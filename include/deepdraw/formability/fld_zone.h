// The zones of the forming-limit diagram (doc/theory_formability.md §5,
// D134): one function classifies a point of the sheet from its in-plane
// major and minor strains and its thickness strain.
#ifndef deepdraw_formability_fld_zone_h
#define deepdraw_formability_fld_zone_h

#include <deepdraw/formability/forming_limit_curve.h>
#include <string>

namespace deepdraw
{
  namespace formability
  {
    // Values are what the VTU field fld_zone holds.
    enum class FldZone : unsigned int
    {
      safe                 = 0,
      marginal             = 1,
      split                = 2,
      thinning             = 3,
      insufficient_stretch = 4,
      wrinkling_tendency   = 5
    };

    // "safe", "marginal", "split", "thinning", "insufficient stretch",
    // "wrinkling tendency".
    std::string
    zone_name(FldZone zone);

    // Thresholds of subsection Formability (logarithmic strains).
    struct FldZoneParameters
    {
      // Marginal: less than this % of the limit major strain below the
      // curve, [0, 100).
      double safety_band = 10.;
      // Thinning: thickness strain ln(t/t0) below this, < 0 (-0.25: 22 %
      // thinner).
      double thinning_limit = -0.25;
      // Insufficient stretch: eps1 < s and eps2 > -s, s >= 0.
      double insufficient_stretch = 0.02;
      // Wrinkling tendency: eps2 <= -w and the sheet thickens, w >= 0.
      double wrinkling_minor_strain = 0.02;
    };

    // The zone of a point, in this order of precedence: split (above the
    // curve), marginal (within the safety band below it), thinning,
    // wrinkling tendency, insufficient stretch, safe. curve may be null (no
    // forming-limit curve): then neither split nor marginal.
    FldZone
    classify(const FormingLimitCurve *curve,
             const FldZoneParameters &parameters,
             double                   major_strain,
             double                   minor_strain,
             double                   thickness_strain);
  } // namespace formability
} // namespace deepdraw

#endif
