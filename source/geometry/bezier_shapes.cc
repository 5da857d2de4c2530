#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deepdraw/geometry/bezier_shapes.h>

namespace deepdraw::geometry
{
  dealii::Tensor<1, 3>
  rotate(const dealii::Tensor<1, 3> &vector,
         const dealii::Tensor<1, 3> &axis,
         const double                angle)
  {
    return std::cos(angle) * vector
           + std::sin(angle) * dealii::cross_product_3d(axis, vector)
           + (1. - std::cos(angle)) * (axis * vector) * axis;
  }


  RationalCurve
  circular_arc(const dealii::Point<3>     &center,
               const dealii::Tensor<1, 3> &start_radius,
               const dealii::Tensor<1, 3> &axis,
               const double                angle)
  {
    AssertThrow(angle > 0. && angle < M_PI,
                dealii::ExcMessage("A rational quadratic arc spans less than "
                                   "180 degrees"));
    const double  half = std::cos(0.5 * angle);
    RationalCurve arc;
    arc.points  = {center + start_radius,
                   center + rotate(start_radius, axis, 0.5 * angle) / half,
                   center + rotate(start_radius, axis, angle)};
    arc.weights = {1., half, 1.};
    return arc;
  }


  RationalCurve
  straight_segment(const dealii::Point<3>    &a,
                   const dealii::Point<3>    &b,
                   const std::vector<double> &weights)
  {
    AssertThrow(weights.size() >= 2,
                dealii::ExcMessage("A segment needs at least two weights"));
    RationalCurve      segment;
    const unsigned int n = weights.size() - 1;
    for (unsigned int i = 0; i <= n; ++i)
      segment.points.push_back(a + (static_cast<double>(i) / n) * (b - a));
    segment.weights = weights;
    return segment;
  }


  BezierPatch
  ruled_patch(const RationalCurve &c0, const RationalCurve &c1)
  {
    AssertThrow(c0.degree() == c1.degree(),
                dealii::ExcMessage("Ruled patch: curves of different degree"));
    std::vector<dealii::Point<3>> points(c0.points);
    points.insert(points.end(), c1.points.begin(), c1.points.end());
    std::vector<double> weights(c0.weights);
    weights.insert(weights.end(), c1.weights.begin(), c1.weights.end());
    return BezierPatch(c0.degree(), 1, points, weights);
  }


  BezierPatch
  extruded_patch(const RationalCurve        &curve,
                 const dealii::Tensor<1, 3> &direction)
  {
    RationalCurve shifted = curve;
    for (dealii::Point<3> &point : shifted.points)
      point += direction;
    return ruled_patch(curve, shifted);
  }


  BezierPatch
  revolved_patch(const RationalCurve        &profile,
                 const dealii::Point<3>     &axis_point,
                 const dealii::Tensor<1, 3> &axis,
                 const double                angle)
  {
    // Each profile control point sweeps an arc about the axis; the weights
    // are the products of the arc and profile weights (NURBS Book §8.5).
    std::vector<dealii::Point<3>> points;
    std::vector<double>           weights;
    for (unsigned int j = 0; j <= profile.degree(); ++j)
    {
      const dealii::Tensor<1, 3> offset = profile.points[j] - axis_point;
      const dealii::Point<3>     foot   = axis_point + (offset * axis) * axis;
      const RationalCurve        arc
        = circular_arc(foot, profile.points[j] - foot, axis, angle);
      for (unsigned int i = 0; i < 3; ++i)
      {
        points.push_back(arc.points[i]);
        weights.push_back(arc.weights[i] * profile.weights[j]);
      }
    }
    return BezierPatch(2, profile.degree(), points, weights);
  }


  BezierPatch
  oriented_towards(const BezierPatch          &patch,
                   const dealii::Tensor<1, 3> &direction)
  {
    if (patch.unit_normal(0.5, 0.5) * direction < 0.)
      return patch.reversed_u();
    return patch;
  }
} // namespace deepdraw::geometry
