// The quadrature-point history of a child point interpolated from its
// parent's 8 Gauss points (doc/theory.md §8, doc/decisions.md D88), the
// alternative to the nearest parent point of D57: the trilinear function
// through the 8 values (interpolation inside the parent's Gauss-point box,
// extrapolation to the child points outside it), exact for fields linear
// in the parent's reference coordinates. The interpolated state is made
// admissible again:
// - the material axes, an interpolated matrix that is no longer a
//   rotation, are replaced by the rotation of its polar decomposition;
// - epbar is kept >= 0;
// - a relative stress xi = sigma - X outside the yield surface
//   (Hill'48 equivalent stress above Y(epbar)) has its deviatoric part
//   scaled back onto it, epbar and X unchanged (no plastic flow is
//   invented; the hydrostatic part, which Hill'48 does not see, stays).
#ifndef deepdraw_adaptivity_history_interpolation_h
#define deepdraw_adaptivity_history_interpolation_h

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deepdraw/fe/quadrature_point_update.h>
#include <deepdraw/material/elasto_plasticity.h>

namespace deepdraw
{
  namespace adaptivity
  {
    using namespace dealii;

    // The rotation nearest to A (the orthogonal factor of A = R U), by the
    // Newton iteration R <- (R + R^-T) / 2 from R = A, to RᵀR = I within
    // 1e-15; A must be near a rotation (det A > 0).
    Tensor<2, 3>
    nearest_rotation(const Tensor<2, 3> &A);

    // Weights of the parent's weighted points of `quadrature` (the 2 x 2 x n
    // Gauss points of fe::selective_reduced_quadrature, whose last point,
    // the centre, carries no history) in the interpolation at xi that is
    // linear in each direction between the two coordinates of the rule
    // bracketing xi (trilinear for n = 2).
    std::vector<double>
    interpolation_weights(const Quadrature<3> &quadrature, const Point<3> &xi);

    // The history at xi (unit cell of the parent) from the parent's points
    // `parent` (in the order of `quadrature`). material: for the return
    // to the yield surface (required).
    fe::QuadraturePointHistory
    interpolate_history(const fe::QuadraturePointHistory *parent,
                        const Quadrature<3>              &quadrature,
                        const Point<3>                   &xi,
                        const material::ElastoPlasticity &material);
  } // namespace adaptivity
} // namespace deepdraw

#endif
