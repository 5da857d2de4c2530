// A pre-stressed material point (plastic, with back-stress) rotated rigidly
// by 90 degrees in several increments: Hughes-Winget with the mid-increment
// gradient gives Q equal to each incremental rotation exactly (Cayley
// transform), so the stress must end as Q sigma Q^T with unchanged
// invariants, and the orthotropy axes must have turned with the material.
// With Hill'48 and with Yld2004-18p (AA2090-T3), both with Prager.
#include "material/material_test_tools.h"
#include "test_utilities.h"

#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/fe/quadrature_point_update.h>
#include <deepdraw/material/elasto_plasticity.h>
#include <deepdraw/material/material_parameters.h>

using namespace dealii;
using namespace deepdraw;

namespace
{
  Tensor<2, 3>
  rotation_matrix(Tensor<1, 3> axis, const double angle)
  {
    axis /= axis.norm();
    Tensor<2, 3> K; // cross-product matrix
    K[0][1] = -axis[2];
    K[0][2] = axis[1];
    K[1][0] = axis[2];
    K[1][2] = -axis[0];
    K[2][0] = -axis[1];
    K[2][1] = axis[0];
    return Tensor<2, 3>(unit_symmetric_tensor<3>()) + std::sin(angle) * K
           + (1. - std::cos(angle)) * K * K;
  }

  double
  second_invariant(const Tensor<2, 3> &s)
  {
    return 0.5 * (trace(s) * trace(s) - trace(s * s));
  }

  void
  rotate_and_check(const Tensor<1, 3>                 &axis,
                   const unsigned int                  n_increments,
                   const material::MaterialParameters &parameters)
  {
    std::cout << "axis " << axis << ", " << n_increments << " increments"
              << std::endl;
    const material::ElastoPlasticity material(parameters);

    // Pre-stress: a plastic multiaxial stretch.
    fe::QuadraturePointHistory state, next;
    Tensor<2, 3>               P;
    bool                       plastic = false;
    Tensor<2, 3>               H;
    H[0][0] = 0.02;
    H[1][1] = -0.005;
    H[0][1] = 0.004;
    H[2][0] = -0.003;
    deepdraw_test::check_true(
      "pre-stressing increment succeeds",
      fe::update_quadrature_point(material, state, H, next, P, nullptr, plastic)
        == fe::PointStatus::ok);
    deepdraw_test::check_true("pre-stress is plastic", plastic);
    state = next;

    const Tensor<2, 3> sigma_0 = fe::cauchy_stress(state);
    const Tensor<2, 3> X_0     = state.material_axes
                             * Tensor<2, 3>(state.state.back_stress)
                             * transpose(state.material_axes);
    const Tensor<2, 3> axes_0           = state.material_axes;
    const double       plastic_strain_0 = state.state.equivalent_plastic_strain;

    const double       angle = 0.5 * M_PI;
    const Tensor<2, 3> step  = rotation_matrix(axis, angle / n_increments);
    for (unsigned int i = 0; i < n_increments; ++i)
    {
      // Rigid rotation of the increment: F = step, H = step - I.
      const Tensor<2, 3> H_rotation
        = step - Tensor<2, 3>(unit_symmetric_tensor<3>());
      fe::update_quadrature_point(material,
                                  state,
                                  H_rotation,
                                  next,
                                  P,
                                  nullptr,
                                  plastic);
      state = next;
    }

    const Tensor<2, 3> Q     = rotation_matrix(axis, angle);
    const Tensor<2, 3> sigma = fe::cauchy_stress(state);
    const Tensor<2, 3> X     = state.material_axes
                           * Tensor<2, 3>(state.state.back_stress)
                           * transpose(state.material_axes);
    const double scale = sigma_0.norm();
    deepdraw_test::check_close("|sigma - Q sigma0 Q^T| / |sigma0|",
                               (sigma - Q * sigma_0 * transpose(Q)).norm()
                                 / scale,
                               0.,
                               1e-8);
    deepdraw_test::check_close("|X - Q X0 Q^T| / |X0|",
                               (X - Q * X_0 * transpose(Q)).norm() / X_0.norm(),
                               0.,
                               1e-8);
    deepdraw_test::check_relative("first invariant",
                                  trace(sigma),
                                  trace(sigma_0),
                                  1e-8);
    deepdraw_test::check_relative("second invariant",
                                  second_invariant(sigma),
                                  second_invariant(sigma_0),
                                  1e-8);
    deepdraw_test::check_relative("third invariant",
                                  determinant(sigma),
                                  determinant(sigma_0),
                                  1e-8);
    deepdraw_test::check_close("|R - Q R0|",
                               (state.material_axes - Q * axes_0).norm(),
                               0.,
                               1e-12);
    deepdraw_test::check_close("no plastic flow during the rotation",
                               state.state.equivalent_plastic_strain
                                 - plastic_strain_0,
                               0.,
                               1e-15);
  }
} // namespace

int
main()
{
  // NUMISHEET'93 aluminium (Hill'48) with Prager hardening.
  material::MaterialParameters parameters;
  parameters.prager_modulus = 2000.;
  rotate_and_check(Tensor<1, 3>({0., 0., 1.}), 9, parameters);
  rotate_and_check(Tensor<1, 3>({1., 2., -0.5}), 30, parameters);
  // Yld2004-18p (AA2090-T3) with Prager hardening.
  std::cout << "Yld2004-18p" << std::endl;
  material::MaterialParameters yld2004 = material_test::aa2090_t3_parameters();
  yld2004.prager_modulus               = 2000.;
  rotate_and_check(Tensor<1, 3>({1., 2., -0.5}), 30, yld2004);
  return deepdraw_test::summary();
}
