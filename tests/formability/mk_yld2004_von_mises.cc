// Yld2004-18p with every coefficient 1 and a = 2 is von Mises
// (doc/theory_material.md §1.2): through Yld2004PlaneStress its equivalent
// stress and gradient are those of Hill'48 with F = G = H = 1/2, N = 3/2 in
// plane stress (a closed form, HillPlaneStress), and the M-K curve of the
// same Swift law is the von Mises curve. The two differ only in how
// sigma_bar is evaluated: Yld2004 through two 3 x 3 eigenproblems, the
// scaled sum of nine powers and phi_0 (round-off 1e-15 relative), Hill'48
// as a square root. The M-K analysis turns such differences into changes
// of its Newton iterates below its tolerance (|R| < 1e-10 per step, some
// 300 steps per path) and of the golden-section search (a comparison of
// two nearly equal limits), so the curves agree to that tolerance, not to
// the bit: measured 6.3e-13 relative at most, 1e-10 (the Newton tolerance)
// allowed. The yield function: measured 4.4e-16 (sigma_bar) and 7.1e-16
// (gradient), 3e-15 allowed.
#include "../test_utilities.h"
#include "formability_test_tools.h"

#include <deepdraw/formability/marciniak_kuczynski.h>
#include <iostream>
#include <random>

using namespace deepdraw;
using namespace formability_test;

int
main()
{
  MaterialParameters von_mises = normal_anisotropy(1., 0.2);
  MaterialParameters yld2004   = von_mises;
  yld2004.yield_criterion      = material::YieldCriterion::yld2004_18p;
  yld2004.yld2004_exponent     = 2.;
  const formability::HillPlaneStress    hill(von_mises);
  const formability::Yld2004PlaneStress barlat(yld2004);

  // The yield function and its gradient at random plane stresses.
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> component(-1., 1.);
  double                                 stress_error = 0., gradient_error = 0.;
  for (unsigned int k = 0; k < 1000; ++k)
  {
    formability::PlaneTensor s;
    s[0][0]            = component(random);
    s[1][1]            = component(random);
    s[0][1]            = component(random);
    const double sigma = hill.equivalent_stress(s);
    stress_error
      = std::max(stress_error,
                 std::abs(barlat.equivalent_stress(s) - sigma) / sigma);
    const formability::PlaneTensor difference
      = barlat.gradient(s) - hill.gradient(s);
    gradient_error = std::max(gradient_error, difference.norm());
  }
  std::cout << "plane stress, 1000 random states: sigma_bar " << stress_error
            << " relative, gradient " << gradient_error << std::endl;
  deepdraw_test::check_close("sigma_bar", stress_error, 0., 3e-15);
  deepdraw_test::check_close("gradient", gradient_error, 0., 3e-15);

  formability::MarciniakKuczynskiParameters parameters;
  const formability::MkHardening            swift(von_mises);
  const formability::MarciniakKuczynski     mk_hill(hill, swift, parameters);
  const formability::MarciniakKuczynski mk_barlat(barlat, swift, parameters);
  const std::vector<formability::MkLimitPoint> reference
    = mk_hill.limit_curve();
  const std::vector<formability::MkLimitPoint> curve = mk_barlat.limit_curve();
  deepdraw_test::check_true("same strain ratios",
                            reference.size() == curve.size());
  double largest = 0.;
  for (unsigned int k = 0; k < std::min(reference.size(), curve.size()); ++k)
  {
    const double relative
      = std::abs(curve[k].major_strain - reference[k].major_strain)
        / reference[k].major_strain;
    largest = std::max(largest, relative);
    std::cout << "rho = " << reference[k].strain_ratio
              << ": von Mises eps1* = " << reference[k].major_strain
              << " (groove " << reference[k].groove_angle
              << " deg), Yld2004 a = 2: " << curve[k].major_strain << " ("
              << curve[k].groove_angle << " deg), " << relative << " relative"
              << std::endl;
    deepdraw_test::check_close("strain ratio",
                               curve[k].strain_ratio,
                               reference[k].strain_ratio,
                               1e-12);
  }
  deepdraw_test::check_close("M-K curve, largest relative difference",
                             largest,
                             0.,
                             1e-10);
  return deepdraw_test::summary();
}
