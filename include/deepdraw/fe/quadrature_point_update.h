// The constitutive update at one quadrature point of the updated-Lagrangian
// formulation (doc/theory.md §1-2), and its exact linearisation.
//
// Chain from H = grad_{x_t}(du) (SRI-modified) to the first Piola-Kirchhoff
// stress relative to the configuration at t:
//   Hughes-Winget: dL = H F_half^{-1}, d_eps = sym dL, dW = skew dL,
//                  Q = (I - dW/2)^{-1}(I + dW/2);
//   material axes R_{n+1} = Q R_n; the strain increment, measured at mid
//                  increment, enters the material frame with the half-step
//                  axes: d_eps^ = R_half^T d_eps R_half, R_half = Q_half R_n;
//   return mapping sigma^_{n+1} = sigma^(state_n, d_eps^) (Hill'48);
//   sigma = R_{n+1} sigma^ R_{n+1}^T, P = det(F) sigma F^{-T}, F = I + H.
// dP/dH differentiates every step of this chain (algorithmic tangent,
// rotation and geometric terms), so Newton converges quadratically.
#ifndef deepdraw_fe_quadrature_point_update_h
#define deepdraw_fe_quadrature_point_update_h

#include <deal.II/base/tensor.h>
#include <deepdraw/material/elasto_plasticity.h>
#include <deepdraw/material/material_point_state.h>

namespace deepdraw
{
  namespace fe
  {
    using namespace dealii;

    // What a quadrature point remembers between increments; committed only
    // when an increment converges.
    struct QuadraturePointHistory
    {
      material::MaterialPointState state; // in the material frame
      // Columns: rolling, transverse and normal directions in global
      // coordinates, sigma = R sigma^ R^T.
      Tensor<2, 3> material_axes = unit_symmetric_tensor<3>();
    };

    enum class PointStatus
    {
      ok,
      inverted,             // det F <= 0
      return_mapping_failed // local Newton of the material did not converge
    };

    // Fills `updated`, P and (if tangent != nullptr) dP/dH with
    // (*tangent)[i][j][k][l] = dP_ij / dH_kl.
    PointStatus
    update_quadrature_point(const material::ElastoPlasticity &material,
                            const QuadraturePointHistory     &old_history,
                            const Tensor<2, 3>               &H,
                            QuadraturePointHistory           &updated,
                            Tensor<2, 3>                     &P,
                            Tensor<4, 3>                     *tangent,
                            bool                             &plastic);

    // Cauchy stress in global coordinates.
    Tensor<2, 3>
    cauchy_stress(const QuadraturePointHistory &history);
  } // namespace fe
} // namespace deepdraw

#endif
