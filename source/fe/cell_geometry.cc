#include <deepdraw/fe/cell_geometry.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>

namespace deepdraw
{
  namespace fe
  {
    void
    compute_cell_geometry(const FEValues<3> &fe_values, CellGeometry &geometry)
    {
      // The constant volumetric gradient is the volume average, not the
      // gradient at the centre: only the average passes the patch test on
      // warped hexahedra (doc/decisions.md D20). 2x2x2 Gauss integrates
      // grad N_a exactly on a trilinear cell, and so does 2x2xn.
      const unsigned int n_points
        = n_weighted_points(fe_values.get_quadrature());
      geometry.gradient.resize(8 * n_points);
      geometry.mode_gradient.resize(max_modes * n_points);
      geometry.JxW.resize(n_points);
      double volume = 0.;
      geometry.mean_gradient.fill(Tensor<1, 3>());
      for (unsigned int q = 0; q < n_points; ++q)
      {
        geometry.JxW[q] = fe_values.JxW(q);
        volume += geometry.JxW[q];
        for (unsigned int a = 0; a < 8; ++a)
        {
          geometry.gradient[q * 8 + a] = fe_values.shape_grad(a, q);
          geometry.mean_gradient[a]
            += geometry.JxW[q] * geometry.gradient[q * 8 + a];
        }
      }
      for (unsigned int a = 0; a < 8; ++a)
        geometry.mean_gradient[a] /= volume;

      // Incompatible modes M_m = xi_m^2 / 4 on the unit cell (xi = 2 x^ - 1
      // in [-1, 1]), grad_x^ M_m = xi_m e_m, mapped with the Jacobian at the
      // centre J0 and scaled by j0 / j (Taylor, Beresford, Wilson 1976;
      // Simo, Armero 1992, Eq. 3.9): int g~_m dV = j0 J0^{-T} int xi_m e_m
      // dx^ = 0, which makes the element pass the patch test on any mesh.
      const Tensor<2, 3> J0     = Tensor<2, 3>(fe_values.jacobian(n_points));
      const double       j0     = determinant(J0);
      const Tensor<2, 3> J0_inv = invert(J0);
      for (unsigned int q = 0; q < n_points; ++q)
      {
        const double    j = determinant(Tensor<2, 3>(fe_values.jacobian(q)));
        const Point<3> &unit_point = fe_values.get_quadrature().point(q);
        for (unsigned int m = 0; m < 3; ++m)
        {
          const double xi = 2. * unit_point[m] - 1.;
          // (J0^{-T} e_m)_i = (J0^{-1})_mi
          for (unsigned int i = 0; i < 3; ++i)
            geometry.mode_gradient[q * max_modes + m][i]
              = j0 / j * xi * J0_inv[m][i];
        }
        // The through-thickness modes, grad_x^ M_4 = (xi_z^2 - 1/3) e_z and
        // grad_x^ M_5 = (xi_z^3 - 3/5 xi_z) e_z (Legendre's P2 and P3 up to
        // a factor): with them the transverse strain of a layer is
        // quadratic (cubic), so that sigma_zz = 0 can hold at each of its 3
        // (4) Gauss points in z (D202). Their integrals vanish under those
        // rules; at 2 (3) points they are zero, and unused.
        const double xi_z = 2. * unit_point[2] - 1.;
        const double thickness_modes[2]
          = {xi_z * xi_z - 1. / 3., xi_z * (xi_z * xi_z - 0.6)};
        for (unsigned int m = 0; m < 2; ++m)
          for (unsigned int i = 0; i < 3; ++i)
            geometry.mode_gradient[q * max_modes + 3 + m][i]
              = j0 / j * thickness_modes[m] * J0_inv[2][i];
      }
    }
  } // namespace fe
} // namespace deepdraw
