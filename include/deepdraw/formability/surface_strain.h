// In-plane logarithmic principal strains of the sheet's surface (or mid
// surface) from the deformation of a surface quadrilateral since t = 0, in
// the current tangent plane of the sheet, wherever it has turned: the wall
// of a cup is vertical (doc/theory_formability.md §1). Pure geometry, exact
// for homogeneous deformations.
#ifndef deepdraw_formability_surface_strain_h
#define deepdraw_formability_surface_strain_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace deepdraw
{
  namespace formability
  {
    struct SurfaceStrain
    {
      // ln(lambda_1) >= ln(lambda_2): the principal stretches of the
      // surface deformation gradient.
      double major_strain = 0.;
      double minor_strain = 0.;
      // Unit direction of the major strain in the current configuration
      // (tangent to the current surface; its sign is arbitrary).
      dealii::Tensor<1, 3> major_direction;
      // Unit normal of the current tangent plane, a_1 x a_2 / |a_1 x a_2|.
      dealii::Tensor<1, 3> normal;
    };

    // From two independent tangent vectors of the initial surface and the
    // same material vectors now (a_i = F A_i): the right Cauchy-Green
    // tensor of the surface in an orthonormal basis of the initial tangent
    // plane, its eigenvalues lambda^2 and eigenvectors. NaN strains if
    // either pair is (nearly) parallel.
    SurfaceStrain
    surface_strain(const std::array<dealii::Tensor<1, 3>, 2> &initial_tangents,
                   const std::array<dealii::Tensor<1, 3>, 2> &current_tangents);

    // A bilinear quadrilateral with corners in deal.II's order (0, 1, 2, 3
    // at (0,0), (1,0), (0,1), (1,1) of the reference square), at its
    // centre: the tangents are the mean of its opposite edges.
    SurfaceStrain
    surface_strain(const std::array<dealii::Point<3>, 4> &initial_corners,
                   const std::array<dealii::Point<3>, 4> &current_corners);
  } // namespace formability
} // namespace deepdraw

#endif
