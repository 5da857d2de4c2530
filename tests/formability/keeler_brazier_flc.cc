// The Keeler-Brazier curve against its formula, evaluated here by hand:
// FLC0 = (23.3 + 14.13 t) n / 0.21 % engineering major strain, the left
// side eps1 + eps2 = ln(1 + FLC0) (constant thickness strain), the right
// side e1 = FLC0 + 0.6 e2 in engineering strains; refused outside
// 0 < n <= 0.21, 0 < t <= 3 mm with the source of the value named.
// Measured 4e-16 relative at most (round-off): 2e-15 allowed.
#include "../test_utilities.h"

#include <deepdraw/formability/keeler_brazier_flc.h>
#include <deepdraw/io/input_error.h>

using namespace deepdraw;
using namespace formability;

namespace
{
  bool
  refused(const double n, const double t, const std::string &expected)
  {
    try
    {
      KeelerBrazierFlc(n, t, "Material/Swift exponent", "Geometry/Thickness");
    }
    catch (const InputError &error)
    {
      std::cout << "  message: " << error.what() << std::endl;
      return std::string(error.what()).find(expected) != std::string::npos;
    }
    return false;
  }
} // namespace

int
main()
{
  // (n, t, FLC0 %): 37.43 * 0.2/0.21, 34.604 * 0.15/0.21, 65.69 * 1.
  const double cases[3][3] = {{0.2, 1., 35.6476190476190476},
                              {0.15, 0.8, 24.7171428571428571},
                              {0.21, 3., 65.69}};
  for (const auto &c : cases)
  {
    const KeelerBrazierFlc curve(c[0], c[1], "n", "t");
    const std::string      what
      = "n = " + std::to_string(c[0]) + ", t = " + std::to_string(c[1]);
    deepdraw_test::check_relative(what + ": FLC0 (%)",
                                  KeelerBrazierFlc::flc0_percent(c[0], c[1]),
                                  c[2],
                                  2e-15);
    const double e0 = c[2] / 100.;
    deepdraw_test::check_relative(what + ": eps1 at eps2 = 0",
                                  curve.limit_major_strain(0.),
                                  std::log(1. + e0),
                                  2e-15);
    deepdraw_test::check_relative(what + ": left side at eps2 = -0.1",
                                  curve.limit_major_strain(-0.1),
                                  std::log(1. + e0) + 0.1,
                                  2e-15);
    const double e2 = std::exp(0.1) - 1.;
    deepdraw_test::check_relative(what + ": right side at eps2 = 0.1",
                                  curve.limit_major_strain(0.1),
                                  std::log(1. + e0 + 0.6 * e2),
                                  2e-15);
  }
  deepdraw_test::check_true("n = 0.36 refused, source named",
                            refused(0.36, 1., "Material/Swift exponent"));
  deepdraw_test::check_true("t = 3.5 mm refused, source named",
                            refused(0.2, 3.5, "Geometry/Thickness"));
  deepdraw_test::check_true("n = 0 refused", refused(0., 1., "0 < n <= 0.21"));
  return deepdraw_test::summary();
}
