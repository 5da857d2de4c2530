// The hardening law of the M-K analysis (MkHardening) and its inverse
// epbar(Y) (doc/theory_formability.md §4.6): the safeguarded
// Newton-bisection against the closed forms, written here, of Swift,
// epbar = (Y/C)^(1/n) - eps0, and Voce, epbar = -ln((A - Y)/B) / C; a table
// inverted exactly at and between its points and on its extrapolation;
// +infinity at and above the saturation (Voce's A, a flat last segment), 0
// at and below Y(0); the refusal of laws that do not harden.
#include "../test_utilities.h"

#include <deepdraw/formability/mk_hardening.h>
#include <deepdraw/io/input_error.h>
#include <iostream>

using namespace deepdraw;
using material::HardeningLawType;
using material::MaterialParameters;

namespace
{
  double
  relative(const double a, const double b)
  {
    return std::abs(a - b) / std::max(std::abs(b), 1e-300);
  }
} // namespace


int
main()
{
  MaterialParameters swift; // the aluminium: C = 576.79, eps0, n = 0.3593
  const formability::MkHardening swift_law(swift);
  double                         swift_error = 0.;
  for (const double e : {1e-6, 1e-3, 0.05, 0.3, 1., 4., 20.})
  {
    const double Y = swift_law.yield_stress(e);
    // Relative to eps0 + epbar: the closed form subtracts eps0 and loses
    // digits at small epbar (5.7e-12 relative at epbar = 1e-6).
    swift_error = std::max(swift_error,
                           std::abs(swift_law.solve_equivalent_strain(Y)
                                    - swift_law.equivalent_strain(Y))
                             / (0.01658 + e));
  }
  std::cout << "Swift: iteration against the closed form " << swift_error
            << " relative to eps0 + epbar" << std::endl;
  deepdraw_test::check_close("Swift inverse", swift_error, 0., 1e-14);
  deepdraw_test::check_true("Swift does not saturate",
                            std::isinf(swift_law.saturation_stress()));
  deepdraw_test::check_close("Swift necking strain = n",
                             swift_law.necking_strain(),
                             0.3593,
                             0.);

  MaterialParameters voce;
  voce.hardening_law = HardeningLawType::voce; // A = 413, B = 280.8, C = 6.5
  const formability::MkHardening voce_law(voce);
  double                         voce_error = 0.;
  for (const double Y : {133., 150., 250., 400., 412., 412.99})
  {
    const double closed_form = -std::log((413. - Y) / 280.8) / 6.5;
    voce_error               = std::max(voce_error,
                          relative(voce_law.equivalent_strain(Y), closed_form));
  }
  std::cout << "Voce: iteration against the closed form " << voce_error
            << " relative" << std::endl;
  deepdraw_test::check_close("Voce inverse", voce_error, 0., 1e-12);
  deepdraw_test::check_close("Voce below Y(0)",
                             voce_law.equivalent_strain(100.),
                             0.,
                             0.);
  deepdraw_test::check_true("Voce at and above A: +infinity",
                            std::isinf(voce_law.equivalent_strain(413.))
                              && std::isinf(voce_law.equivalent_strain(500.)));
  deepdraw_test::check_close("Voce saturation",
                             voce_law.saturation_stress(),
                             413.,
                             0.);
  // The uniaxial Considere strain: B C exp(-C e) = A - B exp(-C e).
  deepdraw_test::check_close("Voce necking strain",
                             voce_law.necking_strain(),
                             std::log(280.8 * 7.5 / 413.) / 6.5,
                             1e-12);

  MaterialParameters table;
  table.hardening_law   = HardeningLawType::tabulated;
  table.hardening_table = {{0., 100.}, {0.1, 150.}, {0.3, 190.}};
  const formability::MkHardening table_law(table);
  deepdraw_test::check_close("table node",
                             table_law.equivalent_strain(150.),
                             0.1,
                             1e-15);
  deepdraw_test::check_close("table segment",
                             table_law.equivalent_strain(170.),
                             0.2,
                             1e-15);
  deepdraw_test::check_close("table extrapolated",
                             table_law.equivalent_strain(230.),
                             0.5,
                             1e-15);
  table.hardening_table = {{0., 100.}, {0.1, 150.}, {0.3, 150.}};
  const formability::MkHardening flat_law(table);
  deepdraw_test::check_close("flat end: saturation",
                             flat_law.saturation_stress(),
                             150.,
                             0.);
  deepdraw_test::check_true("flat end: +infinity above it",
                            std::isinf(flat_law.equivalent_strain(150.5)));
  deepdraw_test::check_close("flat end: below it",
                             flat_law.equivalent_strain(125.),
                             0.05,
                             1e-15);

  // Laws without hardening are named.
  const auto refusal = [](MaterialParameters p)
  { return formability::MkHardening(p).without_hardening(); };
  MaterialParameters p = swift;
  p.swift_exponent     = 0.;
  deepdraw_test::check_true("Swift n = 0 refused",
                            refusal(p).find("Material/Swift exponent") == 0);
  p        = voce;
  p.voce_B = 0.;
  deepdraw_test::check_true("Voce B = 0 refused",
                            refusal(p).find("Material/Voce B") == 0);
  p        = voce;
  p.voce_C = 0.;
  deepdraw_test::check_true("Voce C = 0 refused",
                            refusal(p).find("Material/Voce C") == 0);
  p                 = table;
  p.hardening_table = {{0., 100.}};
  deepdraw_test::check_true("one-point table refused",
                            refusal(p).find("Material/Hardening table") == 0);
  deepdraw_test::check_true("hardening laws accepted",
                            refusal(swift).empty() && refusal(voce).empty());
  return deepdraw_test::summary();
}
