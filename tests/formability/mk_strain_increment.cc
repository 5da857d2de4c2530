// The M-K curve does not depend on the strain increment of the integration:
// the default material (NUMISHEET'93 aluminium, Hill'48 with r0 = 0.71,
// Swift n = 0.359) and the default M-K parameters (f0 = 0.99, steps of
// 0.001 in groove strain) against steps of half that size, at every strain
// ratio of the curve. The issue asks for 1 %; measured (printed) 0.072 %
// at most, so 0.2 % is required: the integration is first order and the
// crossing of the localisation factor is interpolated between steps.
#include "../test_utilities.h"

#include <deepdraw/formability/marciniak_kuczynski.h>
#include <iostream>

using namespace deepdraw;

int
main()
{
  const material::MaterialParameters        material;
  formability::HillPlaneStress              yield(material);
  formability::MarciniakKuczynskiParameters coarse, fine;
  fine.strain_increment = 0.5 * coarse.strain_increment;
  const formability::MkHardening               swift(material);
  const std::vector<formability::MkLimitPoint> a
    = formability::MarciniakKuczynski(yield, swift, coarse).limit_curve();
  const std::vector<formability::MkLimitPoint> b
    = formability::MarciniakKuczynski(yield, swift, fine).limit_curve();
  deepdraw_test::check_true("same strain ratios", a.size() == b.size());
  double largest = 0.;
  for (unsigned int k = 0; k < a.size() && k < b.size(); ++k)
  {
    const double difference
      = std::abs(a[k].major_strain - b[k].major_strain) / b[k].major_strain;
    largest = std::max(largest, difference);
    std::cout << "rho " << a[k].strain_ratio << ": eps1* " << a[k].major_strain
              << " / " << b[k].major_strain << " (groove " << a[k].groove_angle
              << " / " << b[k].groove_angle << " degrees), difference "
              << difference * 100. << " %" << std::endl;
  }
  deepdraw_test::check_close("largest relative difference", largest, 0., 2e-3);
  return deepdraw_test::summary();
}
