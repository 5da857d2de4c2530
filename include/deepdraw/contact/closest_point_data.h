// What the contact kinematics needs to know of the tool surface at the
// closest point of one node. The solver fills it from the geometry layer's
// projection; the contact area does not depend on the geometry headers.
#ifndef deepdraw_contact_closest_point_data_h
#define deepdraw_contact_closest_point_data_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace deepdraw
{
  namespace contact
  {
    // Surface x̄(u, v) of the tool in its current position, at the
    // parameters (u, v) of the closest point of the node.
    struct ClosestPointData
    {
      // x̄: the foot point.
      dealii::Point<3> foot_point;
      // n: unit normal, pointing towards the sheet side of the tool
      // (the gap g_N = (x − x̄)·n is positive when open). Must be orthogonal
      // to both tangents.
      dealii::Tensor<1, 3> normal;
      // ∂x̄/∂u, ∂x̄/∂v. Left zero, the curvature terms are skipped (frozen
      // normal and foot point).
      dealii::Tensor<1, 3> tangent_u;
      dealii::Tensor<1, 3> tangent_v;
      // ∂²x̄/∂u², ∂²x̄/∂u∂v, ∂²x̄/∂v² (zero on a plane).
      dealii::Tensor<1, 3> second_derivative_uu;
      dealii::Tensor<1, 3> second_derivative_uv;
      dealii::Tensor<1, 3> second_derivative_vv;
    };
  } // namespace contact
} // namespace deepdraw

#endif
