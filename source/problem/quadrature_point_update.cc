#include <deepdraw/kinematics/hughes_winget_increment.h>
#include <deepdraw/problem/quadrature_point_update.h>

namespace deepdraw
{
  namespace problem
  {
    PointStatus
    update_quadrature_point(const material::HillPlasticity &material,
                            const QuadraturePointHistory   &old_history,
                            const Tensor<2, 3>             &H,
                            QuadraturePointHistory         &updated,
                            Tensor<2, 3>                   &P,
                            Tensor<4, 3>                   *tangent,
                            bool                           &plastic)
    {
      kinematics::HughesWingetIncrement increment;
      if (!increment.reinit(H))
        return PointStatus::inverted;

      const Tensor<2, 3> &R_old = old_history.material_axes;
      const Tensor<2, 3>  R     = increment.rotation * R_old;
      const Tensor<2, 3>  RT    = transpose(R);
      // d_eps lives in the mid-increment configuration: measure it in the
      // axes rotated by half the increment (second-order accurate).
      const Tensor<2, 3> R_half  = increment.half_rotation * R_old;
      const Tensor<2, 3> R_halfT = transpose(R_half);
      const Tensor<2, 3> strain_increment(increment.strain_increment);
      const SymmetricTensor<2, 3> material_strain_increment =
        symmetrize(R_halfT * strain_increment * R_half);

      SymmetricTensor<4, 3> algorithmic_tangent;
      if (!material.update(old_history.state,
                           material_strain_increment,
                           updated.state,
                           algorithmic_tangent,
                           plastic))
        return PointStatus::return_mapping_failed;
      updated.material_axes = R;

      const Tensor<2, 3> material_stress(updated.state.stress);
      const Tensor<2, 3> sigma   = R * material_stress * RT;
      const Tensor<2, 3> F_inv_T = transpose(increment.inverse_deformation_gradient);
      const double       J       = increment.jacobian;
      const Tensor<2, 3> sigma_F_inv_T = sigma * F_inv_T;
      P                                = J * sigma_F_inv_T;

      if (tangent == nullptr)
        return PointStatus::ok;

      // Directional derivative along dH = e_k (x) e_l for all k, l.
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = 0; l < 3; ++l)
          {
            Tensor<2, 3> dH;
            dH[k][l] = 1.;
            Tensor<2, 3> d_strain, d_spin, dQ, dQ_half;
            increment.variation(dH, d_strain, d_spin, dQ, dQ_half);
            const Tensor<2, 3> dR      = dQ * R_old;
            const Tensor<2, 3> dRT     = transpose(dR);
            const Tensor<2, 3> dR_half = dQ_half * R_old;
            const SymmetricTensor<2, 3> d_material_strain = symmetrize(
              transpose(dR_half) * strain_increment * R_half
              + R_halfT * d_strain * R_half
              + R_halfT * strain_increment * dR_half);
            const Tensor<2, 3> d_material_stress(algorithmic_tangent
                                                 * d_material_strain);
            const Tensor<2, 3> d_sigma = dR * material_stress * RT
                                         + R * d_material_stress * RT
                                         + R * material_stress * dRT;
            // dJ = J tr(F^{-1} dH) = J F^{-1}_{lk};
            // d(F^{-T}) = -F^{-T} dH^T F^{-T}.
            const double dJ = J * F_inv_T[k][l];
            const Tensor<2, 3> dP =
              dJ * sigma_F_inv_T + J * d_sigma * F_inv_T
              - J * sigma_F_inv_T * transpose(dH) * F_inv_T;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                (*tangent)[i][j][k][l] = dP[i][j];
          }
      return PointStatus::ok;
    }



    Tensor<2, 3>
    cauchy_stress(const QuadraturePointHistory &history)
    {
      const Tensor<2, 3> &R = history.material_axes;
      return R * Tensor<2, 3>(history.state.stress) * transpose(R);
    }
  } // namespace problem
} // namespace deepdraw
