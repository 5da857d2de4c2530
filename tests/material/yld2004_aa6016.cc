// The two Yld2004-18p parameter sets of AA6016-T4 in the ESAFORM 2021 cup
// drawing benchmark (Habraken et al., Int. J. Material Forming 15 (2022)),
// identified by NTNU and by Postech, against the directionality another
// implementation lists for them.
//
// Source: S. C. Soare's public repositories nnYS (3D/yld2004Param_NTNU.txt,
// yld2004Param_Postech.txt: the transformations as L = C T acting on the
// stress, order (L11, L12, L21, L22, L31, L32, c66, c55, c44)) and PolyN
// (CM_Data/AA6016_Parameters/AA6016T4_TUAT_Yld2004_*_Err_and_Coeff.txt:
// the "Predicted" uniaxial stresses and r-values at 0, 15, ..., 90 deg and
// the balanced biaxial stress, from the exact polynomial form of Yld2004
// with a = 8, raw formula phi = 4 sigma_bar^8). The c's below follow from L
// by c12 = L11 - L12, c13 = 2 L11 + L12, c21 = L22 - L21, c23 = 2 L22 + L21,
// c31 = -(2 L31 + L32), c32 = -(L31 + 2 L32) (doc/theory_material.md §1.2)
// and come out with four decimals.
//
// Model: ElastoPlasticity::update, perfectly plastic, uniaxial tension
// through the driver; its yield stresses are normalised to the rolling
// direction, the listed ones are raw, so they are compared after the factor
// (phi_0 / 4)^(-1/8). The listed values have four decimals: 6e-5 absolute.
#include "../test_utilities.h"
#include "material_test_tools.h"

#include <deepdraw/material/elasto_plasticity.h>

using namespace material_test;

namespace
{
  struct Listed
  {
    std::string           name;
    std::array<double, 9> c1, c2;
    std::array<double, 7> stress, r; // 0, 15, ..., 90 deg
    double                biaxial;
  };

  void
  check(const Listed &set)
  {
    std::cout << set.name << std::endl;
    MaterialParameters p = aa2090_t3_parameters(); // a = 8, Yld2004-18p
    p.yld2004_c1         = set.c1;
    p.yld2004_c2         = set.c2;
    p.swift_exponent     = 0.;
    p.swift_coefficient  = 300.;
    const ElastoPlasticity material(p);
    const double           raw
      = std::pow(material.yld2004_criterion().raw_rolling_direction_factor(),
                 -1. / 8.);
    std::cout << "  raw rolling-direction yield stress " << raw << std::endl;
    for (unsigned int k = 0; k < 7; ++k)
    {
      const UniaxialFlow flow  = uniaxial_flow(material, 15. * k);
      const std::string  label = "  " + std::to_string(15 * k) + " deg: ";
      deepdraw_test::check_true(label + "converged, plastic", flow.ok);
      deepdraw_test::check_close(label + "raw yield stress",
                                 flow.stress / 300. * raw,
                                 set.stress[k],
                                 6e-5);
      deepdraw_test::check_close(label + "r", flow.r(), set.r[k], 6e-5);
    }
    deepdraw_test::check_close(
      "  balanced biaxial raw yield stress",
      raw / material.equivalent_stress(strain(1., 1., 0., 0., 0., 0.)),
      set.biaxial,
      6e-5);
  }
} // namespace


int
main()
{
  // c12 c13 c21 c23 c31 c32 c44 c55 c66 of C' and C''.
  check({"NTNU",
         {{1.1998, 1.2289, 0.1315, 0.8081, 1.1386, 0.287, 1., 1., 1.3739}},
         {{1.151, -0.2576, 0.4873, 0.9934, 0.911, 0.7965, 1., 1., 0.2679}},
         {{0.9987, 0.9518, 0.9026, 0.8973, 0.8993, 0.9396, 0.9679}},
         {{0.5235, 0.3550, 0.3009, 0.2416, 0.3104, 0.3823, 0.6002}},
         0.9574});
  check(
    {"Postech",
     {{1., 1., -0.087, 0.4496, 1.0192, 1.1724, 1.2801, 1.1487, 0.}},
     {{1.3329, 1.251, 1.0948, 1.0855, -0.0065, 0.4812, 0.5991, 0.7366, 1.5461}},
     {{0.9875, 0.9622, 0.9157, 0.8912, 0.9065, 0.9464, 0.9699}},
     {{0.4965, 0.3987, 0.2821, 0.2644, 0.3176, 0.4561, 0.5567}},
     0.9859});
  return deepdraw_test::summary();
}
