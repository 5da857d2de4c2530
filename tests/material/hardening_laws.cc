// Voce and tabulated hardening (doc/theory_material.md §1.3): the law
// itself against its closed form / the table, and uniaxial tension in the
// rolling direction through ElastoPlasticity::update against it.
//
// Why uniaxial rolling-direction tension tests the law alone: the criterion
// is normalised so that sigma_bar = sigma_11 there, and plastic-work
// equivalence sigma_bar d(epbar) = sigma_11 d(eps^p_11) gives epbar =
// eps^p_11 = eps_11 - sigma_11 / E. So after every step the axial stress must
// equal Y(eps_11 - sigma_11 / E), computed here from the driver's total
// strain and stress only. The update solves its scalar equation to 1e-13 Y
// and the driver its stress residual to 1e-10 MPa: agreement to 1e-9
// relative is asked (observed ~1e-13); a wrong slope or a knot taken from
// the wrong side of the table gives errors of 1e-3 and more.
#include "../test_utilities.h"
#include "material_test_tools.h"

#include <deepdraw/material/elasto_plasticity.h>
#include <deepdraw/material/hardening_law.h>

using namespace material_test;
using deepdraw::material::HardeningLaw;
using deepdraw::material::HardeningLawType;

namespace
{
  // Strain-driven uniaxial tension along the rolling direction to eps_max
  // in n steps; returns max |sigma_11 - Y(eps^p_11)| / Y.
  template <typename Law>
  double
  uniaxial_error(const MaterialParameters &p,
                 const Law                &law,
                 const double              eps_max,
                 const unsigned int        n,
                 double                   &epbar)
  {
    const ElastoPlasticity material(p);
    UniaxialDriver         driver(material, 0.);
    double                 worst = 0.;
    for (unsigned int step = 0; step < n; ++step)
    {
      if (!driver.strain_step(eps_max / n))
        return 1e300;
      const double s    = driver.stress()[0][0];
      const double ep11 = driver.strain()[0][0] - s / p.youngs_modulus;
      worst             = std::max(worst, std::abs(s - law(ep11)) / law(ep11));
    }
    epbar = driver.state.equivalent_plastic_strain;
    return worst;
  }


  double
  table_value(const std::vector<std::pair<double, double>> &t, const double e)
  {
    // Written out independently: find the segment by a linear scan.
    unsigned int k = 0;
    while (k + 2 < t.size() && e >= t[k + 1].first)
      ++k;
    const double slope
      = (t[k + 1].second - t[k].second) / (t[k + 1].first - t[k].first);
    return t[k].second + slope * (e - t[k].first);
  }
} // namespace


int
main()
{
  // Voce: Y = A - B exp(-C epbar), the AA6016-T4 fit of the ESAFORM 2021
  // benchmark (A = 314.98, B = 189.03, C = 12.22 MPa).
  {
    std::cout << "Voce" << std::endl;
    MaterialParameters p;
    p.hardening_law = HardeningLawType::voce;
    p.voce_A        = 314.98;
    p.voce_B        = 189.03;
    p.voce_C        = 12.22;
    const auto voce = [&](const double e)
    { return p.voce_A - p.voce_B * std::exp(-p.voce_C * e); };
    const HardeningLaw law(p);
    for (const double e : {0., 0.01, 0.1, 0.5})
    {
      deepdraw_test::check_relative("  Y(" + std::to_string(e) + ")",
                                    law.yield_stress(e),
                                    voce(e),
                                    1e-15);
      deepdraw_test::check_relative("  Y'(" + std::to_string(e) + ")",
                                    law.hardening_modulus(e),
                                    p.voce_C * p.voce_B
                                      * std::exp(-p.voce_C * e),
                                    1e-15);
    }
    double       epbar = 0.;
    const double error = uniaxial_error(p, voce, 0.3, 60, epbar);
    std::cout << "  epbar after 30 % strain: " << epbar << std::endl;
    deepdraw_test::check_close("  uniaxial RD tension, max |sigma - Y| / Y",
                               error,
                               0.,
                               1e-9);
  }

  // Tabulated: four points with different slopes, crossed by the test and
  // extrapolated beyond the last one (slope of the last segment).
  {
    std::cout << "tabulated" << std::endl;
    MaterialParameters p;
    p.hardening_law   = HardeningLawType::tabulated;
    p.hardening_table = {{0., 150.}, {0.02, 190.}, {0.1, 250.}, {0.2, 280.}};
    const HardeningLaw                           law(p);
    const auto                                  &t        = p.hardening_table;
    const std::vector<std::pair<double, double>> expected = {{0., 150.},
                                                             {0.01, 170.},
                                                             {0.02, 190.},
                                                             {0.06, 220.},
                                                             {0.2, 280.},
                                                             {0.3, 310.}};
    for (const auto &[e, Y] : expected)
      deepdraw_test::check_relative("  Y(" + std::to_string(e) + ")",
                                    law.yield_stress(e),
                                    Y,
                                    1e-14);
    deepdraw_test::check_relative("  slope on the second segment",
                                  law.hardening_modulus(0.05),
                                  750.,
                                  1e-14);
    deepdraw_test::check_relative("  slope beyond the last point",
                                  law.hardening_modulus(0.5),
                                  300.,
                                  1e-14);
    double       epbar = 0.;
    const double error = uniaxial_error(
      p,
      [&](const double e) { return table_value(t, e); },
      0.3,
      97,
      epbar);
    std::cout << "  epbar after 30 % strain: " << epbar << std::endl;
    deepdraw_test::check_true("  the test crosses every point and goes beyond",
                              epbar > 0.2);
    deepdraw_test::check_close("  uniaxial RD tension, max |sigma - Y| / Y",
                               error,
                               0.,
                               1e-9);

    // One point: perfectly plastic.
    p.hardening_table = {{0., 200.}};
    const HardeningLaw flat(p);
    deepdraw_test::check_close("  single point: Y(0.7)",
                               flat.yield_stress(0.7),
                               200.,
                               0.);
    deepdraw_test::check_close("  single point: Y'",
                               flat.hardening_modulus(0.7),
                               0.,
                               0.);
  }

  // Swift through HardeningLaw: its closed form.
  {
    const MaterialParameters p;
    const HardeningLaw       law(p);
    deepdraw_test::check_relative("Swift Y(0.2)",
                                  law.yield_stress(0.2),
                                  p.swift_coefficient
                                    * std::pow(p.swift_prestrain + 0.2,
                                               p.swift_exponent),
                                  1e-15);
  }
  return deepdraw_test::summary();
}
