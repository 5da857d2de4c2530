#include <deepdraw/fe/quadrature_point_update.h>
#include <deepdraw/kinematics/hughes_winget_increment.h>

namespace deepdraw
{
  namespace fe
  {
    PointStatus
    update_quadrature_point(const material::ElastoPlasticity &material,
                            const QuadraturePointHistory     &old_history,
                            const Tensor<2, 3>               &H,
                            QuadraturePointHistory           &updated,
                            Tensor<2, 3>                     &P,
                            Tensor<4, 3>                     *tangent,
                            bool                             &plastic)
    {
      kinematics::HughesWingetIncrement increment;
      if (!increment.reinit(H))
        return PointStatus::inverted;

      const Tensor<2, 3> &R_old = old_history.material_axes;
      const Tensor<2, 3>  R     = increment.rotation * R_old;
      const Tensor<2, 3>  RT    = transpose(R);
      // d_eps lives in the mid-increment configuration: measure it in the
      // axes rotated by half the increment (second-order accurate).
      const Tensor<2, 3>          R_half  = increment.half_rotation * R_old;
      const Tensor<2, 3>          R_halfT = transpose(R_half);
      const Tensor<2, 3>          strain_increment(increment.strain_increment);
      const SymmetricTensor<2, 3> material_strain_increment
        = symmetrize(R_halfT * strain_increment * R_half);

      SymmetricTensor<4, 3> algorithmic_tangent;
      if (!material.update(old_history.state,
                           material_strain_increment,
                           updated.state,
                           algorithmic_tangent,
                           plastic))
        return PointStatus::return_mapping_failed;
      updated.material_axes = R;

      const Tensor<2, 3> material_stress(updated.state.stress);
      const Tensor<2, 3> sigma = R * material_stress * RT;
      const Tensor<2, 3> F_inv_T
        = transpose(increment.inverse_deformation_gradient);
      const double       J             = increment.jacobian;
      const Tensor<2, 3> sigma_F_inv_T = sigma * F_inv_T;
      P                                = J * sigma_F_inv_T;

      if (tangent == nullptr)
        return PointStatus::ok;

      // dP/dH by linearity rather than 9 directional derivatives with a
      // mostly-zero dH: sigma depends on H only through G = d(dL), and
      //   d(dL) = F_half^{-1} dH F_half^{-1}   (I - dL/2 = F_half^{-1}),
      // so we first take the response S(G) of sigma to the 6 symmetric and
      // 3 skew unit G (9 small chains instead of 9 full ones), then
      //   d sigma / dH_kl = sum_mn F_half^{-1}_mk F_half^{-1}_ln S(e_m (x)
      //   e_n).
      // With Q = A^{-1} (I + dW/2), A = I - dW/2: I + Q = 2 A^{-1}, hence
      //   dR = dQ R_n = A^{-1} dW A^{-1} R_n, dR_half = 1/2 A_h^{-1} dW
      //   A_h^{-1} R_n (A_h = I - dW/4): the Cayley-transform derivative
      // dQ = A^{-1} (d dW / 2) (I + Q) written without its (I + Q) factor.
      const Tensor<2, 3> identity = unit_symmetric_tensor<3>();
      const Tensor<2, 3> F_half_inv
        = identity - 0.5 * increment.velocity_gradient_increment;
      const Tensor<2, 3> A_inv = 0.5 * (identity + increment.rotation);
      const Tensor<2, 3> A_half_inv
        = 0.5 * (identity + increment.half_rotation);
      const Tensor<2, 3> A_inv_R      = A_inv * R_old;
      const Tensor<2, 3> A_half_inv_R = A_half_inv * R_old;
      const Tensor<2, 3> stress_RT    = material_stress * RT;
      const Tensor<2, 3> RhT_strain   = R_halfT * strain_increment;

      // response[m][n] = S(e_m (x) e_n) = S(sym) + S(skew) of that G.
      Tensor<2, 3> response[3][3];
      // d sigma = R (C : d eps^) R^T, with d eps^ = R_half^T dE R_half for a
      // symmetric dE (no rotation of the axes).
      for (unsigned int m = 0; m < 3; ++m)
        for (unsigned int n = m; n < 3; ++n)
        {
          SymmetricTensor<2, 3> d_material_strain;
          for (unsigned int p = 0; p < 3; ++p)
            for (unsigned int q = p; q < 3; ++q)
              d_material_strain[p][q]
                = 0.5
                  * (R_half[m][p] * R_half[n][q] + R_half[n][p] * R_half[m][q]);
          response[m][n]
            = R * Tensor<2, 3>(algorithmic_tangent * d_material_strain) * RT;
          response[n][m] = response[m][n];
        }
      // A skew G = dW_mn / 2 with dW_mn = e_m (x) e_n - e_n (x) e_m rotates
      // the axes: d sigma = Y + Y^T + R (C : d eps^) R^T, Y = dR sigma^ R^T,
      // d eps^ = Z + Z^T, Z = R_half^T d_eps dR_half.
      for (unsigned int m = 0; m < 3; ++m)
        for (unsigned int n = m + 1; n < 3; ++n)
        {
          Tensor<2, 3> dR, dR_half;
          for (unsigned int p = 0; p < 3; ++p)
            for (unsigned int q = 0; q < 3; ++q)
            {
              dR[p][q]
                = A_inv[p][m] * A_inv_R[n][q] - A_inv[p][n] * A_inv_R[m][q];
              dR_half[p][q] = 0.5
                              * (A_half_inv[p][m] * A_half_inv_R[n][q]
                                 - A_half_inv[p][n] * A_half_inv_R[m][q]);
            }
          const Tensor<2, 3>          Z                 = RhT_strain * dR_half;
          const SymmetricTensor<2, 3> d_material_strain = 2. * symmetrize(Z);
          const Tensor<2, 3>          Y                 = dR * stress_RT;
          const Tensor<2, 3>          skew_response
            = 0.5
              * (Y + transpose(Y)
                 + R * Tensor<2, 3>(algorithmic_tangent * d_material_strain)
                     * RT);
          response[m][n] += skew_response;
          response[n][m] -= skew_response;
        }

      // d sigma / dH_kl = sum_m F_half^{-1}_mk T[m][l],
      // T[m][l] = sum_n F_half^{-1}_ln response[m][n]; times J F^{-T}.
      Tensor<2, 3> T[3][3];
      for (unsigned int m = 0; m < 3; ++m)
        for (unsigned int l = 0; l < 3; ++l)
          T[m][l] = J
                    * (F_half_inv[l][0] * response[m][0]
                       + F_half_inv[l][1] * response[m][1]
                       + F_half_inv[l][2] * response[m][2])
                    * F_inv_T;
      // dP = dJ sigma F^{-T} + J d sigma F^{-T} - J sigma F^{-T} dH^T F^{-T}
      // with dJ = J F^{-1}_lk and sigma F^{-T} dH^T F^{-T} =
      // (sigma F^{-T})_il F^{-T}_kj for dH = e_k (x) e_l.
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = 0; l < 3; ++l)
        {
          const double dJ = J * F_inv_T[k][l];
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              (*tangent)[i][j][k][l]
                = dJ * sigma_F_inv_T[i][j] + F_half_inv[0][k] * T[0][l][i][j]
                  + F_half_inv[1][k] * T[1][l][i][j]
                  + F_half_inv[2][k] * T[2][l][i][j]
                  - J * sigma_F_inv_T[i][l] * F_inv_T[k][j];
        }
      return PointStatus::ok;
    }


    Tensor<2, 3>
    cauchy_stress(const QuadraturePointHistory &history)
    {
      const Tensor<2, 3> &R = history.material_axes;
      return R * Tensor<2, 3>(history.state.stress) * transpose(R);
    }
  } // namespace fe
} // namespace deepdraw
