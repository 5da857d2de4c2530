// A forming-limit curve (FLC): the limit major strain eps1*(eps2) of the
// sheet as a function of the minor strain, in logarithmic (true) in-plane
// strains, and the margin of a point below it along the major strain
// (doc/theory_formability.md §2). Implementations: TabulatedFlc (a lab's
// table, and the computed Marciniak-Kuczynski curve), KeelerBrazierFlc.
#ifndef deepdraw_formability_forming_limit_curve_h
#define deepdraw_formability_forming_limit_curve_h

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace deepdraw
{
  namespace formability
  {
    // A point of a curve as it is listed (flc.csv): the strain ratio and
    // the critical groove angle (degrees) of an M-K point, NaN otherwise.
    struct FlcPoint
    {
      double minor_strain = 0.;
      double major_strain = 0.;
      double strain_ratio = std::numeric_limits<double>::quiet_NaN();
      double groove_angle = std::numeric_limits<double>::quiet_NaN();
    };

    // The distance of a point to the curve along the major strain:
    // eps1*(eps2) - eps1 (positive below the curve, where the sheet is
    // safe) and the same in % of eps1*(eps2).
    struct FlcMargin
    {
      double strain  = 0.;
      double percent = 0.;
    };

    class FormingLimitCurve
    {
    public:
      virtual ~FormingLimitCurve() = default;

      // eps1*(eps2), > 0.
      virtual double
      limit_major_strain(double minor_strain) const = 0;

      // The points that describe the curve, by increasing minor strain: a
      // table's nodes, or samples of a closed-form curve.
      virtual std::vector<FlcPoint>
      points() const = 0;

      // One line for titles and messages ("Keeler-Brazier, n = 0.2, ...").
      virtual std::string
      description() const = 0;

      // The minor strains where the curve is given: a table's first and
      // last point (an M-K curve's uniaxial and equibiaxial ends); beyond
      // them a table is only held at its end values (D131). The whole line
      // for a closed-form curve (Keeler-Brazier).
      virtual std::pair<double, double>
      minor_strain_range() const;

      // Whether eps2 lies outside minor_strain_range(): a margin read there
      // is not measured by the curve (D172).
      bool
      beyond_range(double minor_strain) const;

      FlcMargin
      margin(double major_strain, double minor_strain) const;
    };
  } // namespace formability
} // namespace deepdraw

#endif
