#include <cmath>
#include <deepdraw/contact/contact_pair_kinematics.h>

namespace deepdraw
{
  namespace contact
  {
    ContactPairKinematics::ContactPairKinematics(
      const dealii::Point<3>           &position,
      const dealii::Tensor<1, 3>       &displacement_increment,
      const geometry::ProjectionResult &closest_point,
      const dealii::Tensor<1, 3>       &tool_translation_increment,
      const dealii::Tensor<1, 3>       &tool_axis,
      const Linearisation               linearisation)
        : n(closest_point.normal)
        , curvature_included(false)
    {
      // d: relative motion of node and tool in the increment.
      const dealii::Tensor<1, 3> d
        = displacement_increment - tool_translation_increment;
      const dealii::Tensor<1, 3> x_minus_foot = position - closest_point.foot;
      g_N                                     = x_minus_foot * n;
      g_T                                     = d - (d * n) * n;
      g                                       = g_N * n + g_T;

      // Every variation enters through δd = δΔu − a δz: the node moves by
      // δΔu and the tool (foot point and Δx̄_tool) by a δz.
      for (unsigned int i = 0; i < 3; ++i)
        dg_ddu[i][i] = 1.;

      if (linearisation == Linearisation::full)
      {
        const dealii::Tensor<1, 3> S[2]
          = {closest_point.tangent_u, closest_point.tangent_v};
        const dealii::Tensor<1, 3> S2[2][2]
          = {{closest_point.x_uu, closest_point.x_uv},
             {closest_point.x_uv, closest_point.x_vv}};

        // Metric A, curvature B = n·x̄_,αβ, and the Hessian of the
        // distance H = A − (x − x̄)·x̄_,αβ of the closest-point problem.
        dealii::Tensor<2, 2> A, B, H;
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int b = 0; b < 2; ++b)
          {
            A[a][b] = S[a] * S[b];
            B[a][b] = n * S2[a][b];
            H[a][b] = A[a][b] - x_minus_foot * S2[a][b];
          }
        const double det_A = determinant(A);
        const double scale = S[0].norm_square() * S[1].norm_square();
        if (det_A > 1e-12 * scale && std::abs(determinant(H)) > 1e-10 * det_A)
        {
          // dξ = H⁻¹ Gᵀ δd and dn = −G A⁻¹ B dξ, so dn = −C δd with
          // C = Σ M_αβ x̄_,α ⊗ x̄_,β, M = A⁻¹ B H⁻¹.
          const dealii::Tensor<2, 2> M = invert(A) * B * invert(H);
          dealii::Tensor<2, 3>       C;
          for (unsigned int a = 0; a < 2; ++a)
            for (unsigned int b = 0; b < 2; ++b)
              C += M[a][b] * outer_product(S[a], S[b]);

          // δĝ = δd + (g_N − d·n) δn + n ((x − x̄ − d)·δn), from
          // δg_N = n·δd + (x − x̄)·δn and δ[(I − n⊗n) d].
          dn_ddu = -C;
          dg_ddu += -(g_N - d * n) * C
                    - outer_product(n, transpose(C) * (x_minus_foot - d));
          curvature_included = true;
        }
      }

      dg_dz = -(dg_ddu * tool_axis);
      dn_dz = -(dn_ddu * tool_axis);
    }


    double
    ContactPairKinematics::normal_gap() const
    {
      return g_N;
    }


    const dealii::Tensor<1, 3> &
    ContactPairKinematics::tangential_slip() const
    {
      return g_T;
    }


    const dealii::Tensor<1, 3> &
    ContactPairKinematics::gap() const
    {
      return g;
    }


    const dealii::Tensor<1, 3> &
    ContactPairKinematics::normal() const
    {
      return n;
    }


    const dealii::Tensor<2, 3> &
    ContactPairKinematics::dgap_ddisplacement() const
    {
      return dg_ddu;
    }


    const dealii::Tensor<1, 3> &
    ContactPairKinematics::dgap_dtool_position() const
    {
      return dg_dz;
    }


    const dealii::Tensor<2, 3> &
    ContactPairKinematics::dnormal_ddisplacement() const
    {
      return dn_ddu;
    }


    const dealii::Tensor<1, 3> &
    ContactPairKinematics::dnormal_dtool_position() const
    {
      return dn_dz;
    }


    bool
    ContactPairKinematics::curvature_terms_included() const
    {
      return curvature_included;
    }
  } // namespace contact
} // namespace deepdraw
