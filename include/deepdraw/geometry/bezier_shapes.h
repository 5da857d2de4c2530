// Exact rational Bézier constructions of the shapes tools are made of:
// circular arcs, straight segments and the patches swept from them (ruled
// surfaces, extrusions, surfaces of revolution: planes, cylinders, cones,
// spheres, tori).
#ifndef deepdraw_geometry_bezier_shapes_h
#define deepdraw_geometry_bezier_shapes_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deepdraw/geometry/bezier_patch.h>
#include <vector>

namespace deepdraw::geometry
{
  // A rational Bézier curve: degree + 1 control points and weights.
  struct RationalCurve
  {
    std::vector<dealii::Point<3>> points;
    std::vector<double>           weights;

    unsigned int
    degree() const
    {
      return points.size() - 1;
    }
  };

  // Rotation of `vector` by `angle` (radians) about the unit `axis`
  // (Rodrigues' formula).
  dealii::Tensor<1, 3>
  rotate(const dealii::Tensor<1, 3> &vector,
         const dealii::Tensor<1, 3> &axis,
         double                      angle);

  // Arc from center + start_radius, turning counter-clockwise about the unit
  // `axis` (perpendicular to start_radius) by `angle` in (0, pi): the
  // rational quadratic with the middle control point at the intersection of
  // the end tangents and weights (1, cos(angle / 2), 1) (NURBS Book §7.3).
  RationalCurve
  circular_arc(const dealii::Point<3>     &center,
               const dealii::Tensor<1, 3> &start_radius,
               const dealii::Tensor<1, 3> &axis,
               double                      angle);

  // The segment from a to b as a rational curve with the given weights and
  // equally spaced control points (a straight line for any positive weights;
  // matching the weights of an arc makes a ruled surface between the two
  // regular).
  RationalCurve
  straight_segment(const dealii::Point<3>    &a,
                   const dealii::Point<3>    &b,
                   const std::vector<double> &weights = {1., 1.});

  // x(u, v) = (1 - v) c0(u) + v c1(u) in homogeneous coordinates; c0 and c1
  // must have the same degree. Degrees (degree, 1).
  BezierPatch
  ruled_patch(const RationalCurve &c0, const RationalCurve &c1);

  // x(u, v) = c(u) + v direction. Degrees (degree, 1).
  BezierPatch
  extruded_patch(const RationalCurve        &curve,
                 const dealii::Tensor<1, 3> &direction);

  // The profile (parameter v) revolved about the axis through axis_point
  // with unit direction axis by `angle` in (0, pi) (parameter u).
  // Degrees (2, profile degree).
  BezierPatch
  revolved_patch(const RationalCurve        &profile,
                 const dealii::Point<3>     &axis_point,
                 const dealii::Tensor<1, 3> &axis,
                 double                      angle);

  // `patch`, or patch.reversed_u() if its normal at the parameter centre
  // points away from `direction`.
  BezierPatch
  oriented_towards(const BezierPatch          &patch,
                   const dealii::Tensor<1, 3> &direction);
} // namespace deepdraw::geometry

#endif
