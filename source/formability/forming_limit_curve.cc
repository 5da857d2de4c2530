// The margin of a point below a forming-limit curve
// (doc/theory_formability.md §2).
#include <deepdraw/formability/forming_limit_curve.h>

namespace deepdraw
{
  namespace formability
  {
    FlcMargin
    FormingLimitCurve::margin(const double major_strain,
                              const double minor_strain) const
    {
      const double limit = limit_major_strain(minor_strain);
      FlcMargin    result;
      result.strain  = limit - major_strain;
      result.percent = 100. * result.strain / limit;
      return result;
    }


    std::pair<double, double>
    FormingLimitCurve::minor_strain_range() const
    {
      return {-std::numeric_limits<double>::infinity(),
              std::numeric_limits<double>::infinity()};
    }


    bool
    FormingLimitCurve::beyond_range(const double minor_strain) const
    {
      const auto [low, high] = minor_strain_range();
      return minor_strain < low || minor_strain > high;
    }
  } // namespace formability
} // namespace deepdraw
