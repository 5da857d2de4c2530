// The M-K curve of a Voce law against that of a table sampled from the same
// Voce curve (Material/Hardening law = tabulated), both with the default
// Hill'48 aluminium: the table is the Voce curve up to its sampling error,
// the piecewise-linear interpolation error h^2/8 |Y''| in stress and h/2
// |Y''| in slope for a spacing h, so the curves must approach each other as
// h falls. Voce A = 413, B = 280.8, C = 6.5 (the default, D124), sampled
// every h = 0.01 and 0.005 up to epbar = 5 (extrapolated beyond with the
// last slope, far beyond any strain of the analysis). Measured 1.8e-3
// (h = 0.01) and 5.8e-4 (h = 0.005) relative at most, both at FLC0 (the
// right side 3e-5 to 7e-5 for h = 0.005); allowed: 2e-3 relative for
// h = 0.005 at every strain ratio, and the difference of h = 0.005 at most
// half that of h = 0.01.
#include "../test_utilities.h"

#include <deepdraw/formability/marciniak_kuczynski.h>
#include <iostream>

using namespace deepdraw;

namespace
{
  std::vector<formability::MkLimitPoint>
  curve(const material::MaterialParameters &material)
  {
    const formability::HillPlaneStress        yield(material);
    formability::MarciniakKuczynskiParameters parameters;
    return formability::MarciniakKuczynski(yield,
                                           formability::MkHardening(material),
                                           parameters)
      .limit_curve();
  }
} // namespace


int
main()
{
  material::MaterialParameters voce;
  voce.hardening_law = material::HardeningLawType::voce;
  const std::vector<formability::MkLimitPoint> reference = curve(voce);

  double       largest[2]  = {0., 0.};
  const double spacings[2] = {0.01, 0.005};
  for (unsigned int s = 0; s < 2; ++s)
  {
    material::MaterialParameters table = voce;
    table.hardening_law                = material::HardeningLawType::tabulated;
    table.hardening_table.clear();
    for (unsigned int k = 0; k * spacings[s] <= 5. + 1e-12; ++k)
    {
      const double e = k * spacings[s];
      table.hardening_table.emplace_back(e, 413. - 280.8 * std::exp(-6.5 * e));
    }
    const std::vector<formability::MkLimitPoint> sampled = curve(table);
    deepdraw_test::check_true("same strain ratios",
                              sampled.size() == reference.size());
    for (unsigned int k = 0; k < std::min(sampled.size(), reference.size());
         ++k)
    {
      const double difference
        = std::abs(sampled[k].major_strain - reference[k].major_strain)
          / reference[k].major_strain;
      largest[s] = std::max(largest[s], difference);
      std::cout << "h = " << spacings[s]
                << ", rho = " << reference[k].strain_ratio
                << ": Voce eps1* = " << reference[k].major_strain << ", table "
                << sampled[k].major_strain << " (" << difference << " relative)"
                << std::endl;
    }
  }
  std::cout << "largest relative difference: h = 0.01 " << largest[0]
            << ", h = 0.005 " << largest[1] << std::endl;
  deepdraw_test::check_close("table h = 0.005 against Voce",
                             largest[1],
                             0.,
                             2e-3);
  deepdraw_test::check_true("the difference falls with the spacing",
                            largest[1] <= 0.5 * largest[0]);
  return deepdraw_test::summary();
}
