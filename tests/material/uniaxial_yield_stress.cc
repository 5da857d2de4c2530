// Yield stress in uniaxial tension at an angle theta to the rolling
// direction. With sigma = s e(x)e, e = (cos, sin, 0), Hill'48 gives
//   sigma_bar^2 / s^2 = F sin^4 + G cos^4 + H (cos^2 - sin^2)^2
//                       + 2 N sin^2 cos^2,
// so s_y = Y / sqrt(G + H) at 0 deg, Y / sqrt(F + H) at 90 deg and
// Y / sqrt((F + G)/4 + N/2) at 45 deg.
//  (a) Swift, virgin material: the stress level at which a stress-driven
//      step (Newton on the strain increment with the tangent) first turns
//      plastic, found by bisection, equals the prediction with Y = C eps0^n.
//  (b) Perfect plasticity (n = 0): strain-driven tension far into the plastic
//      range (mixed control, the 5 other stresses zero); the plateau stress
//      equals the prediction with Y = C, i.e. the return mapping lands on the
//      right point of the yield surface in a rotated direction.
// Tolerance 1e-8 relative: the bisection ends at 1e-14, the local return
// mapping converges to 1e-13, the Newton of the driver to 1e-10 MPa.
#include "../test_utilities.h"
#include "material_test_tools.h"

#include <deepdraw/material/elasto_plasticity.h>
#include <map>

using namespace material_test;

namespace
{
  double
  hill_uniaxial_factor(const MaterialParameters &p, const double degrees)
  {
    const double t = degrees * M_PI / 180., c2 = std::pow(std::cos(t), 2),
                 s2 = std::pow(std::sin(t), 2);
    return std::sqrt(p.hill_F * s2 * s2 + p.hill_G * c2 * c2
                     + p.hill_H * (c2 - s2) * (c2 - s2)
                     + 2. * p.hill_N * s2 * c2);
  }
} // namespace

int
main()
{
  const double angles[] = {0., 30., 45., 60., 90.};

  std::cout << "(a) initial yield, NUMISHEET'93 aluminium (Swift)" << std::endl;
  {
    const MaterialParameters p;
    const ElastoPlasticity   material(p);
    const double             Y0
      = p.swift_coefficient * std::pow(p.swift_prestrain, p.swift_exponent);
    // Explicit closed forms of the brief at 0, 45, 90 deg.
    const std::map<double, double> closed_form
      = {{0., Y0 / std::sqrt(p.hill_G + p.hill_H)},
         {45., Y0 / std::sqrt((p.hill_F + p.hill_G) / 4. + p.hill_N / 2.)},
         {90., Y0 / std::sqrt(p.hill_F + p.hill_H)}};
    for (const double angle : angles)
    {
      const auto plastic_at = [&](const double s)
      {
        UniaxialDriver driver(material, angle);
        if (!driver.stress_step(s))
          throw std::runtime_error("stress-driven step failed");
        return driver.plastic;
      };
      double low = 0.5 * Y0, high = 2. * Y0;
      deepdraw_test::check_true("  bracket",
                                !plastic_at(low) && plastic_at(high));
      while (high - low > 1e-14 * high)
      {
        const double mid               = 0.5 * (low + high);
        (plastic_at(mid) ? high : low) = mid;
      }
      const double expected = Y0 / hill_uniaxial_factor(p, angle);
      deepdraw_test::check_relative("  " + std::to_string(int(angle))
                                      + " deg: first plastic stress",
                                    high,
                                    expected,
                                    1e-8);
      if (closed_form.count(angle))
        deepdraw_test::check_relative("  " + std::to_string(int(angle))
                                        + " deg: closed form",
                                      high,
                                      closed_form.at(angle),
                                      1e-8);
      // Just above yield: the state is uniaxial in the load frame.
      UniaxialDriver driver(material, angle);
      driver.stress_step(high * (1. + 1e-6));
      deepdraw_test::check_close("  lateral stress (load frame) [MPa]",
                                 driver.stress()[1][1],
                                 0.,
                                 1e-9);
    }
    deepdraw_test::check_true("  anisotropy: s_y(0) != s_y(45)",
                              std::abs(hill_uniaxial_factor(p, 0.)
                                       - hill_uniaxial_factor(p, 45.))
                                > 1e-3);
  }

  std::cout << "(b) plateau, perfectly plastic, anisotropic" << std::endl;
  {
    MaterialParameters p;
    p.swift_exponent    = 0.;
    p.swift_coefficient = 200.;
    p.hill_F            = 0.25;
    p.hill_G            = 0.8;
    p.hill_H            = 0.4;
    p.hill_N            = 1.9;
    p.hill_L            = 1.2;
    p.hill_M            = 1.4;
    const ElastoPlasticity material(p);
    for (const double angle : angles)
    {
      UniaxialDriver driver(material, angle);
      bool           ok = true;
      for (unsigned int step = 0; step < 20; ++step)
        ok = ok && driver.strain_step(1e-3);
      deepdraw_test::check_true("  20 strain steps of 1e-3 converged, plastic",
                                ok && driver.plastic);
      const SymmetricTensor<2, 3> s = driver.stress();
      deepdraw_test::check_relative("  " + std::to_string(int(angle))
                                      + " deg: plateau stress",
                                    s[0][0],
                                    p.swift_coefficient
                                      / hill_uniaxial_factor(p, angle),
                                    1e-8);
      deepdraw_test::check_close("  axial strain",
                                 driver.strain()[0][0],
                                 0.02,
                                 1e-14);
      deepdraw_test::check_close("  largest other stress [MPa]",
                                 std::max({std::abs(s[1][1]),
                                           std::abs(s[2][2]),
                                           std::abs(s[0][1]),
                                           std::abs(s[0][2]),
                                           std::abs(s[1][2])}),
                                 0.,
                                 1e-9);
    }
  }
  return deepdraw_test::summary();
}
