// Tension-compression cycle with Prager kinematic hardening (k > 0).
//  (a) Von Mises + Swift + Prager, uniaxial along 1 (mixed strain control).
//      In uniaxial tension X = k eps^p diag(1, -1/2, -1/2) and
//      sigma_bar(sigma e1(x)e1 - X) = |sigma - 3/2 k eps^p_11|, so
//        forward:  sigma_f = Y(eps^p) + Xu,  Xu = 3/2 k eps^p  (eps^p = epbar)
//        reverse yield: sigma_r = Xu - Y(eps^p) = sigma_f - 2 Y(eps^p),
//      i.e. the elastic range is centred on Xu (Bauschinger offset 2 Xu with
//      respect to isotropic hardening, whose reverse yield is -sigma_f).
//      Further compression: sigma_c = 3/2 k eps^p_11 - Y(2 eps^p_f - eps^p_11).
//      The expectations are solved here by bisection (independent scalar
//      equations with eps^p_11 = eps_11 - sigma / E); tolerance 1e-8
//      relative (driver 1e-10 MPa, bisection to the last bit).
//  (b) Hill'48 (NUMISHEET'93 aluminium) + Prager along the rolling
//      direction: X is no longer uniaxial, the reverse yield stress is the
//      second root of sigma_bar(s e1(x)e1 - X)^2 = Y(epbar)^2 (a quadratic
//      in s, evaluated with the Hill formula written here), with X and epbar
//      from the state; the forward stress is the first root.
// The reverse-yield point is found by bisection on a stress-driven unloading
// step (elastic or plastic) from the loaded state.
#include "../test_utilities.h"
#include "material_test_tools.h"

#include <deepdraw/material/elasto_plasticity.h>

using namespace material_test;

namespace
{
  // Stress level of first plastic response when unloading from driver's
  // state towards compression by one stress-driven step.
  double
  reverse_yield(const UniaxialDriver &loaded,
                const double          low,
                const double          high)
  {
    const auto plastic_at = [&](const double s)
    {
      UniaxialDriver driver = loaded;
      if (!driver.stress_step(s))
        throw std::runtime_error("stress-driven step failed");
      return driver.plastic;
    };
    double elastic = high, plastic = low; // high: still elastic
    if (plastic_at(elastic) || !plastic_at(plastic))
      throw std::runtime_error("reverse-yield bracket");
    while (elastic - plastic > 1e-14 * std::abs(plastic))
    {
      const double mid                      = 0.5 * (elastic + plastic);
      (plastic_at(mid) ? plastic : elastic) = mid;
    }
    return plastic;
  }

  double
  hill_squared(const MaterialParameters &p, const SymmetricTensor<2, 3> &x)
  {
    return p.hill_F * std::pow(x[1][1] - x[2][2], 2)
           + p.hill_G * std::pow(x[2][2] - x[0][0], 2)
           + p.hill_H * std::pow(x[0][0] - x[1][1], 2)
           + 2.
               * (p.hill_L * x[1][2] * x[1][2] + p.hill_M * x[0][2] * x[0][2]
                  + p.hill_N * x[0][1] * x[0][1]);
  }
} // namespace

int
main()
{
  std::cout << "(a) von Mises + Swift + Prager k = 2000 MPa" << std::endl;
  {
    MaterialParameters p = von_mises_parameters();
    p.prager_modulus     = 2000.;
    const ElastoPlasticity material(p);
    const double           E = p.youngs_modulus, k = p.prager_modulus;
    const auto             Y = [&](const double e)
    {
      return p.swift_coefficient
             * std::pow(p.swift_prestrain + e, p.swift_exponent);
    };

    UniaxialDriver driver(material, 0.);
    bool           ok = true;
    for (unsigned int step = 0; step < 25; ++step)
      ok = ok && driver.strain_step(2e-3); // to 5 %
    deepdraw_test::check_true("tension to 5 % converged", ok && driver.plastic);
    const double eps     = driver.strain()[0][0];
    const double sigma_f = bisect(
      [&](const double s)
      {
        const double ep = eps - s / E;
        return s - Y(ep) - 1.5 * k * ep;
      },
      0.,
      E * eps);
    const double ep_f = eps - sigma_f / E;
    const double Xu   = 1.5 * k * ep_f;
    std::cout << "  eps^p = " << ep_f << ", Y = " << Y(ep_f)
              << " MPa, Xu = 3/2 k eps^p = " << Xu << " MPa" << std::endl;
    deepdraw_test::check_relative("forward stress sigma_f",
                                  driver.stress()[0][0],
                                  sigma_f,
                                  1e-8);
    deepdraw_test::check_relative("epbar = eps^p_11",
                                  driver.state.equivalent_plastic_strain,
                                  ep_f,
                                  1e-8);
    deepdraw_test::check_relative("X_11 = k eps^p",
                                  driver.back_stress()[0][0],
                                  k * ep_f,
                                  1e-8);
    deepdraw_test::check_relative("X_22 = -k eps^p / 2",
                                  driver.back_stress()[1][1],
                                  -0.5 * k * ep_f,
                                  1e-8);

    const double sigma_r_expected = sigma_f - 2. * Y(ep_f);
    const double sigma_r = reverse_yield(driver, -2. * sigma_f, sigma_f - 1.);
    std::cout << "  sigma_f = " << sigma_f << " MPa, reverse yield " << sigma_r
              << " MPa (isotropic hardening would give " << -sigma_f << ")"
              << std::endl;
    deepdraw_test::check_relative("reverse yield = sigma_f - 2 Y",
                                  sigma_r,
                                  sigma_r_expected,
                                  1e-8);
    deepdraw_test::check_relative("centre of the elastic range = Xu",
                                  0.5 * (sigma_r + sigma_f),
                                  Xu,
                                  1e-8);
    deepdraw_test::check_relative("Bauschinger offset sigma_r + sigma_f = 2 Xu",
                                  sigma_r + sigma_f,
                                  2. * Xu,
                                  1e-8);

    // Compression to -5 % total strain.
    for (unsigned int step = 0; step < 50; ++step)
      ok = ok && driver.strain_step(-2e-3);
    deepdraw_test::check_true("compression to -5 % converged",
                              ok && driver.plastic);
    const double eps_c   = driver.strain()[0][0];
    const double sigma_c = bisect(
      [&](const double s)
      {
        const double ep = eps_c - s / E;
        return s - 1.5 * k * ep + Y(2. * ep_f - ep);
      },
      -E * 0.2,
      0.);
    const double ep_c = eps_c - sigma_c / E;
    deepdraw_test::check_relative("compressive stress at -5 %",
                                  driver.stress()[0][0],
                                  sigma_c,
                                  1e-8);
    deepdraw_test::check_relative("epbar = 2 eps^p_f - eps^p_11",
                                  driver.state.equivalent_plastic_strain,
                                  2. * ep_f - ep_c,
                                  1e-8);
  }

  std::cout << "(b) Hill'48 aluminium + Prager k = 2000 MPa, rolling direction"
            << std::endl;
  {
    MaterialParameters p;
    p.prager_modulus = 2000.;
    const ElastoPlasticity material(p);
    UniaxialDriver         driver(material, 0.);
    bool                   ok = true;
    for (unsigned int step = 0; step < 25; ++step)
      ok = ok && driver.strain_step(2e-3);
    deepdraw_test::check_true("tension to 5 % converged", ok && driver.plastic);
    const SymmetricTensor<2, 3> X = driver.back_stress();
    const double                Yp
      = p.swift_coefficient
        * std::pow(p.swift_prestrain + driver.state.equivalent_plastic_strain,
                   p.swift_exponent);
    // h(s) = sigma_bar(s e1(x)e1 - X)^2 - Y^2 = a s^2 + b s + c.
    const auto h = [&](const double s)
    {
      SymmetricTensor<2, 3> xi = -X;
      xi[0][0] += s;
      return hill_squared(p, xi) - Yp * Yp;
    };
    const double c = h(0.), a = 0.5 * (h(1.) + h(-1.)) - c,
                 b    = 0.5 * (h(1.) - h(-1.));
    const double root = std::sqrt(b * b - 4. * a * c);
    const double s_f = (-b + root) / (2. * a), s_r = (-b - root) / (2. * a);
    std::cout << "  X = " << X << ", Y = " << Yp << ", forward " << s_f
              << ", predicted reverse yield " << s_r << std::endl;
    deepdraw_test::check_true("back stress has transverse components",
                              std::abs(X[1][1]) > 1. && std::abs(X[2][2]) > 1.);
    deepdraw_test::check_relative("forward stress on the shifted surface",
                                  driver.stress()[0][0],
                                  s_f,
                                  1e-8);
    const double sigma_r = reverse_yield(driver, -2. * s_f, s_f - 1.);
    deepdraw_test::check_relative("reverse yield stress", sigma_r, s_r, 1e-8);
    deepdraw_test::check_relative("offset s_f + s_r = -b/a (2x the shift)",
                                  sigma_r + driver.stress()[0][0],
                                  -b / a,
                                  1e-8);
    deepdraw_test::check_true(
      "Bauschinger effect: |reverse| < forward - 10 MPa",
      std::abs(sigma_r) < s_f - 10.);
  }
  return deepdraw_test::summary();
}
