// The effect of the r-value on the M-K curve with Hill'48, in the direction
// the literature reports: with Hill's quadratic criterion a larger r lowers
// the limit strains towards equibiaxial stretching (the "anomalous"
// prediction, Sowerby & Duncan 1971; Graf & Hosford 1990, Metall. Trans. A
// 21, 87-94; Banabic 2010, Sheet Metal Forming Processes, ch. 6), since the
// yield locus of a large r is elongated along equibiaxial tension and its
// normal turns quickly there; in plane strain r has no effect for a
// power-law material (the scalar relation of mk_plane_strain.cc depends on
// r only through eps0). Normal anisotropy r = 0.5, 1, 2; n = 0.2,
// f0 = 0.99. The plane-strain limits differ by 4.7e-5 relative at most
// (measured; eps0 = 1e-4 and the steps): 2e-4 allowed.
#include "../test_utilities.h"
#include "formability_test_tools.h"

#include <deepdraw/formability/marciniak_kuczynski.h>
#include <iostream>

using namespace deepdraw;
using namespace formability_test;

int
main()
{
  std::vector<double> equibiaxial, plane_strain, right_side;
  for (const double r : {0.5, 1., 2.})
  {
    const MaterialParameters     material = normal_anisotropy(r, 0.2);
    formability::HillPlaneStress yield(material);
    formability::MarciniakKuczynskiParameters parameters;
    const formability::MarciniakKuczynski     mk(yield,
                                             formability::MkHardening(material),
                                             parameters);
    equibiaxial.push_back(mk.limit_point(1.).major_strain);
    right_side.push_back(mk.limit_point(0.5).major_strain);
    plane_strain.push_back(mk.limit_point(0.).major_strain);
    std::cout << "r = " << r
              << ": eps1* at rho = 0, 0.5, 1: " << plane_strain.back() << ", "
              << right_side.back() << ", " << equibiaxial.back() << std::endl;
  }
  deepdraw_test::check_true("equibiaxial limit falls as r grows (0.5, 1, 2)",
                            equibiaxial[0] > equibiaxial[1]
                              && equibiaxial[1] > equibiaxial[2]);
  deepdraw_test::check_true("limit at rho = 0.5 falls as r grows",
                            right_side[0] > right_side[1]
                              && right_side[1] > right_side[2]);
  for (unsigned int k = 0; k < 3; k += 2)
    deepdraw_test::check_relative("plane strain limit independent of r",
                                  plane_strain[k],
                                  plane_strain[1],
                                  2e-4);
  return deepdraw_test::summary();
}
