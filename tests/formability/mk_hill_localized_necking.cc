// The M-K left side approaches Hill's (1952) localized-necking limit as the
// imperfection vanishes (Hutchinson & Neale 1978): for a power-law von
// Mises material and a proportional path eps2 = rho eps1, rho <= 0, a neck
// along the zero-extension direction (tan^2 psi = -rho) forms when
// d sigma_1 / d eps_1 = (1 + rho) sigma_1, i.e. for the Swift law with
// epbar = k eps1, k = (2/sqrt 3) sqrt(1 + rho + rho^2), when
//   eps1* = n / (1 + rho) - eps0 / k   (eps1 + eps2 = n for eps0 = 0).
// The M-K limit falls short of it by about c sqrt(1 - f0) (the groove's
// load maximum is quadratic in its strain), so along f0 = 0.999, 0.9999,
// 0.99999 the gap must shrink by about sqrt(10) = 3.2 each time (measured
// 2.7 to 3.0: at least 2.4 required), the last gap must be small (measured
// 1.8 % and 1.2 %: below 2.5 % required), its extrapolation to f0 = 1 with
// the sqrt(1 - f0) law must give Hill's value (measured 0.34 % and 0.09 %:
// 1 % allowed), and the critical initial groove angle must be Hill's
// zero-extension direction carried back along the homogeneous strain,
// tan psi0 = sqrt(-rho) exp(-(1 - rho) eps1*) (measured 0.14 and 0.01
// degrees off: 0.5 allowed).
#include "../test_utilities.h"
#include "formability_test_tools.h"

#include <deal.II/base/numbers.h>
#include <deepdraw/formability/marciniak_kuczynski.h>
#include <iostream>

using namespace deepdraw;
using namespace formability_test;

int
main()
{
  const double                 n = 0.2, eps0 = 1e-4;
  const MaterialParameters     material = normal_anisotropy(1., n, eps0);
  formability::HillPlaneStress yield(material);
  for (const double rho : {-0.5, -0.25})
  {
    const double k    = 2. / std::sqrt(3.) * std::sqrt(1. + rho + rho * rho);
    const double hill = n / (1. + rho) - eps0 / k;
    std::vector<double>       gaps;
    formability::MkLimitPoint point;
    for (const double f0 : {0.999, 0.9999, 0.99999})
    {
      formability::MarciniakKuczynskiParameters parameters;
      parameters.imperfection = f0;
      const formability::MarciniakKuczynski mk(yield,
                                               formability::MkHardening(
                                                 material),
                                               parameters);
      point = mk.limit_point(rho);
      gaps.push_back(hill - point.major_strain);
      std::cout << "rho = " << rho << ", f0 = " << f0 << ": eps1* "
                << point.major_strain << ", Hill " << hill << ", gap "
                << gaps.back() / hill * 100. << " %, groove angle "
                << point.groove_angle << " degrees" << std::endl;
    }
    const std::string what = "rho = " + std::to_string(rho);
    deepdraw_test::check_true(what
                                + ": the gap shrinks by at least 2.4 per "
                                  "decade of 1 - f0",
                              gaps[0] > 2.4 * gaps[1] && gaps[1] > 2.4 * gaps[2]
                                && gaps[2] > 0.);
    deepdraw_test::check_relative(what + ": f0 = 0.99999",
                                  point.major_strain,
                                  hill,
                                  0.025);
    const double s            = std::sqrt(10.);
    const double last         = hill - gaps[2];
    const double before       = hill - gaps[1];
    const double extrapolated = (s * last - before) / (s - 1.);
    deepdraw_test::check_relative(what + ": extrapolated to f0 = 1",
                                  extrapolated,
                                  hill,
                                  0.01);
    const double psi0
      = std::atan(std::sqrt(-rho) * std::exp(-(1. - rho) * hill)) * 180.
        / dealii::numbers::PI;
    deepdraw_test::check_close(what + ": critical groove angle (degrees)",
                               point.groove_angle,
                               psi0,
                               0.5);
  }
  return deepdraw_test::summary();
}
