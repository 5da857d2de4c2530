// FLC0 of the M-K analysis against the published M-K solution for plane
// strain (formability_test_tools.h: Marciniak & Kuczynski 1967; Marciniak,
// Duncan & Hu 2002, ch. 5), where the groove normal to the major strain
// keeps both zones in plane strain and the analysis reduces to the scalar
// relation g(eps_a) = f0 g(eps_b), solved here by bisection. The same
// localisation factor (10) is used on both sides; the value at factor
// infinity (the groove at its maximum load) is printed for comparison.
// Cases: von Mises with n = 0.2, f0 = 0.98 and n = 0.36, f0 = 0.99, and
// Hill'48 with r = 2 (FLC0 of a power-law material does not depend on r:
// k = epbar/eps1 enters only through eps0). Measured 1.5e-4 to 3.4e-4
// relative (the backward-Euler steps of 0.001 in groove strain and the
// interpolation of the crossing between two steps): 1e-3 allowed.
#include "../test_utilities.h"
#include "formability_test_tools.h"

#include <deepdraw/formability/marciniak_kuczynski.h>
#include <iostream>
#include <limits>

using namespace deepdraw;
using namespace formability_test;

namespace
{
  void
  check(const double r, const double n, const double f0)
  {
    const double                 eps0     = 1e-4;
    const MaterialParameters     material = normal_anisotropy(r, n, eps0);
    formability::HillPlaneStress yield(material);
    formability::MarciniakKuczynskiParameters parameters;
    parameters.imperfection = f0;
    const formability::MarciniakKuczynski mk(yield,
                                             formability::MkHardening(material),
                                             parameters);
    const formability::MkLimitPoint       point = mk.limit_point(0.);

    // Plane strain along 2 = 0: sigma_2 / sigma_1 = r / (1 + r) = alpha and
    // epbar / eps1 = 1 / sqrt(1 - alpha^2) (2/sqrt(3) for von Mises).
    const double alpha = r / (1. + r);
    const double k     = 1. / std::sqrt(1. - alpha * alpha);
    const double reference
      = plane_strain_mk_limit(n, eps0, k, f0, parameters.localisation_factor);
    const double at_peak
      = plane_strain_mk_limit(n,
                              eps0,
                              k,
                              f0,
                              std::numeric_limits<double>::infinity());
    std::cout << "r = " << r << ", n = " << n << ", f0 = " << f0
              << ": M-K FLC0 " << point.major_strain << ", published relation "
              << reference << " (factor 10), " << at_peak
              << " (groove at its maximum load)" << std::endl;
    const std::string what = "FLC0, r = " + std::to_string(r)
                             + ", n = " + std::to_string(n)
                             + ", f0 = " + std::to_string(f0);
    deepdraw_test::check_relative(what, point.major_strain, reference, 1e-3);
    deepdraw_test::check_close(what + ": minor strain",
                               point.minor_strain,
                               0.,
                               1e-12);
    deepdraw_test::check_close(what + ": groove angle",
                               point.groove_angle,
                               0.,
                               0.);
  }
} // namespace


int
main()
{
  check(1., 0.2, 0.98);
  check(1., 0.36, 0.99);
  check(2., 0.2, 0.98);
  return deepdraw_test::summary();
}
