// A point of a parametric surface x(u, v) with its first and second
// derivatives, and the differential geometry derived from them (unit normal,
// fundamental forms, curvature). Used by the patches and by the contact
// linearisation, which needs the variation of the foot point and the normal.
#ifndef deepdraw_geometry_surface_point_h
#define deepdraw_geometry_surface_point_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace deepdraw::geometry
{
  // x and its partial derivatives with respect to the patch parameters.
  struct SurfacePoint
  {
    dealii::Point<3>     position;
    dealii::Tensor<1, 3> x_u, x_v;
    dealii::Tensor<1, 3> x_uu, x_uv, x_vv;
  };

  // Curvature data at a surface point, with n = x_u × x_v / |x_u × x_v|.
  // Index 0 stands for u, 1 for v.
  struct SurfaceCurvature
  {
    // First fundamental form a_ab = x_a · x_b.
    dealii::Tensor<2, 2> metric;
    // Second fundamental form b_ab = x_ab · n.
    dealii::Tensor<2, 2> second_fundamental_form;
    // Surface gradient of the unit normal, dn/dx = -b_ab a^a ⊗ a^b
    // (Weingarten equation n_,a = -b_ab a^b, a^a = a^ab x_b). Symmetric,
    // tangential; its eigenvalues in the tangent plane are the principal
    // curvatures.
    dealii::Tensor<2, 3> normal_gradient;
    // Eigenvalues of dn/dx, smallest first. Sign convention: positive when
    // the surface is convex towards its normal (a sphere with the outward
    // normal has +1/R), so the punch nose and the die shoulder have +1/radius.
    std::array<double, 2> principal_curvatures;
  };

  dealii::Tensor<1, 3>
  unit_normal(const SurfacePoint &point);

  SurfaceCurvature
  compute_curvature(const SurfacePoint &point);
} // namespace deepdraw::geometry

#endif
