// Zones of the forming-limit diagram (doc/theory_formability.md §5, D134).
#include <deepdraw/formability/fld_zone.h>

namespace deepdraw
{
  namespace formability
  {
    std::string
    zone_name(const FldZone zone)
    {
      switch (zone)
      {
        case FldZone::safe:
          return "safe";
        case FldZone::marginal:
          return "marginal";
        case FldZone::split:
          return "split";
        case FldZone::thinning:
          return "thinning";
        case FldZone::insufficient_stretch:
          return "insufficient stretch";
        case FldZone::wrinkling_tendency:
          return "wrinkling tendency";
      }
      return "unknown";
    }


    FldZone
    classify(const FormingLimitCurve *curve,
             const FldZoneParameters &parameters,
             const double             major_strain,
             const double             minor_strain,
             const double             thickness_strain)
    {
      if (curve != nullptr)
      {
        const FlcMargin margin = curve->margin(major_strain, minor_strain);
        // On the curve itself counts as split: the limit is reached.
        if (margin.strain <= 0.)
          return FldZone::split;
        if (margin.percent < parameters.safety_band)
          return FldZone::marginal;
      }
      if (thickness_strain < parameters.thinning_limit)
        return FldZone::thinning;
      // Compressed across the major direction while the sheet thickens: a
      // drawn flange (eps1 > 0 radially) is where wrinkles form (D134).
      if (minor_strain <= -parameters.wrinkling_minor_strain
          && thickness_strain > 0.)
        return FldZone::wrinkling_tendency;
      if (major_strain < parameters.insufficient_stretch
          && minor_strain > -parameters.insufficient_stretch)
        return FldZone::insufficient_stretch;
      return FldZone::safe;
    }
  } // namespace formability
} // namespace deepdraw
