// Simple shear of an elastic point with the Jaumann rate: the closed form of
// the hypoelastic response (Dienes 1979) is
//   sigma_12 = G sin(gamma),  sigma_11 = -sigma_22 = G (1 - cos(gamma)).
// The incremental update (Hughes-Winget rotation, strain increment taken in
// the half-step axes) is second-order accurate: assert the error at
// gamma = 1 with 1000 increments (~4e-8 G expected; bound 1e-6 G) and that
// halving the increment divides the error by about four.
#include "test_utilities.h"

#include <cmath>
#include <deepdraw/fe/quadrature_point_update.h>
#include <deepdraw/material/elasto_plasticity.h>
#include <deepdraw/material/material_parameters.h>

using namespace dealii;
using namespace deepdraw;

namespace
{
  // Largest error of the stress components over G.
  double
  shear_error(const unsigned int n_increments, const bool report)
  {
    material::MaterialParameters parameters;
    parameters.swift_coefficient = 1e12; // stays elastic
    const material::ElastoPlasticity material(parameters);
    const double                     G
      = parameters.youngs_modulus / (2. * (1. + parameters.poissons_ratio));

    const double gamma_end = 1.;
    // x_{n+1} = (I + d_gamma e1 (x) e2) x_n: the same H every increment.
    Tensor<2, 3> H;
    H[0][1] = gamma_end / n_increments;

    fe::QuadraturePointHistory state, next;
    Tensor<2, 3>               P;
    bool                       plastic = false;
    for (unsigned int i = 0; i < n_increments; ++i)
    {
      fe::update_quadrature_point(material,
                                  state,
                                  H,
                                  next,
                                  P,
                                  nullptr,
                                  plastic);
      state = next;
    }
    const Tensor<2, 3> sigma = fe::cauchy_stress(state);
    const double       s12   = std::sin(gamma_end);
    const double       s11   = 1. - std::cos(gamma_end);
    if (report)
    {
      deepdraw_test::check_close("sigma_12 / G", sigma[0][1] / G, s12, 1e-6);
      deepdraw_test::check_close("sigma_11 / G", sigma[0][0] / G, s11, 1e-6);
      deepdraw_test::check_close("sigma_22 / G", sigma[1][1] / G, -s11, 1e-6);
      deepdraw_test::check_close("sigma_33 / G", sigma[2][2] / G, 0., 1e-6);
      deepdraw_test::check_true("stayed elastic", !plastic);
    }
    return std::max({std::abs(sigma[0][1] / G - s12),
                     std::abs(sigma[0][0] / G - s11),
                     std::abs(sigma[1][1] / G + s11)});
  }
} // namespace

int
main()
{
  const double coarse = shear_error(500, false);
  const double fine   = shear_error(1000, true);
  const double order  = std::log2(coarse / fine);
  deepdraw_test::check_close("observed order of accuracy", order, 2., 0.2);
  return deepdraw_test::summary();
}
