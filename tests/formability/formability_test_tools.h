// Materials and closed-form references shared by the formability tests,
// written independently of the code under test.
#ifndef deepdraw_tests_formability_test_tools_h
#define deepdraw_tests_formability_test_tools_h

#include <cmath>
#include <deepdraw/material/material_parameters.h>
#include <functional>

namespace formability_test
{
  using deepdraw::material::MaterialParameters;

  // Hill'48 with normal anisotropy r (r0 = r45 = r90 = r), normalised to
  // G + H = 1 so that sigma_bar is the yield stress along the rolling
  // direction (doc/theory_material.md §1: r0 = H/G, r90 = H/F,
  // r45 = N/(F+G) - 1/2); r = 1 is von Mises (F = G = H = 1/2, N = 3/2).
  // Swift C (eps0 + epbar)^n with a small eps0: nearly a power law.
  inline MaterialParameters
  normal_anisotropy(const double r, const double n, const double eps0 = 1e-4)
  {
    MaterialParameters p;
    p.hill_F            = 1. / (1. + r);
    p.hill_G            = 1. / (1. + r);
    p.hill_H            = r / (1. + r);
    p.hill_N            = (r + 0.5) * 2. / (1. + r);
    p.swift_coefficient = 500.;
    p.swift_prestrain   = eps0;
    p.swift_exponent    = n;
    return p;
  }

  // Root of f on [low, high] by bisection, f(low) and f(high) of opposite
  // signs, to the last bits.
  inline double
  bisect(const std::function<double(double)> &f, double low, double high)
  {
    const bool low_negative = f(low) < 0.;
    for (int k = 0; k < 200; ++k)
    {
      const double middle                             = 0.5 * (low + high);
      ((f(middle) < 0.) == low_negative ? low : high) = middle;
    }
    return 0.5 * (low + high);
  }

  // The M-K analysis in plane strain with the groove normal to the major
  // strain, in closed form (Marciniak & Kuczynski 1967; Marciniak, Duncan
  // & Hu 2002, ch. 5; Hosford & Caddell, the chapter on forming limits):
  // both zones stay in plane strain with the same stress ratio, so the
  // force balance sigma_1 t is, with eps3 = -eps1 and epbar = k eps1,
  //   g(eps_a) = f0 g(eps_b),  g(x) = (eps0 + k x)^n exp(-x).
  // Differentiating, d eps_b / d eps_a = g'(eps_a) / (f0 g'(eps_b)); the
  // limit strain eps_a is where this ratio reaches factor (the equivalent
  // strains have the same ratio). factor = infinity: the groove at its
  // maximum load, g'(eps_b) = 0. k = epbar / eps1 in plane strain.
  inline double
  plane_strain_mk_limit(const double n,
                        const double eps0,
                        const double k,
                        const double f0,
                        const double factor)
  {
    const auto g
      = [&](double x) { return std::pow(eps0 + k * x, n) * std::exp(-x); };
    const auto dg
      = [&](double x) { return g(x) * (n * k / (eps0 + k * x) - 1.); };
    const double peak = n - eps0 / k; // g'(peak) = 0
    // eps_a on the rising branch for a given eps_b.
    const auto eps_a = [&](const double eps_b)
    {
      const double target = f0 * g(eps_b);
      if (g(0.) >= target) // zone a still rigid
        return 0.;
      return bisect([&](double x) { return g(x) - target; }, 0., peak);
    };
    if (std::isinf(factor))
      return eps_a(peak);
    // The ratio falls below factor once zone a yields and rises to
    // infinity at the peak: the last crossing, found downwards from the
    // peak, then bisected.
    const auto excess
      = [&](double e) { return dg(eps_a(e)) - factor * f0 * dg(e); };
    double low = peak;
    while (low > 0. && excess(low) >= 0.)
      low -= 1e-3 * peak;
    return eps_a(bisect(excess, low, peak));
  }
} // namespace formability_test

#endif
