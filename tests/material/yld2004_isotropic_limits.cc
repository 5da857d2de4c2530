// Yld2004-18p with all 18 coefficients 1 is Hosford's isotropic criterion
// (S' = S'' = s, phi = 2 sum_{i<j} |s_i - s_j|^a, doc/theory_material.md
// §1.2), and von Mises for a = 2.
//
// (a) a = 2: sigma_bar = sqrt(3/2) |dev xi| for arbitrary stresses, and the
//     whole update (general return mapping, §4) equals the Hill'48 one with
//     F = G = H = 1/2, L = M = N = 3/2 (closed-form spectral return, §2),
//     with and without Prager: stress, back stress, epbar and tangent. Both
//     are exact up to their local tolerances (1e-13), so 1e-9 relative is
//     asked; a wrong Hessian or a missing Prager term gives 1e-3 and more.
//     Uniaxial tension through the driver at 0, 30, 45, 90 deg: yield stress
//     = Y and r = 1 to 1e-8 (the driver converges to 1e-10 MPa).
// (b) a = 8: sigma_bar equals Hosford's formula of the principal stresses,
//     written here directly, to 1e-14; the plane-strain over uniaxial yield
//     stress ratio, found here by bisection on dHosford/d sigma_2 = 0, is
//     the 1.0894 (to 5e-5, its last digit) and the criterion's own
//     plane-strain point (bisection on its gradient) agrees to 1e-10;
//     equibiaxial over uniaxial is 1 to 1e-14.
#include "../test_utilities.h"
#include "material_test_tools.h"

#include <deepdraw/material/elasto_plasticity.h>

using namespace material_test;
using deepdraw::material::Yld2004Criterion;

namespace
{
  MaterialParameters
  isotropic_yld2004(const double a)
  {
    MaterialParameters p;
    p.yield_criterion  = YieldCriterion::yld2004_18p;
    p.yld2004_exponent = a;
    p.yld2004_c1.fill(1.);
    p.yld2004_c2.fill(1.);
    return p;
  }

  SymmetricTensor<2, 3>
  diagonal(const double s1, const double s2, const double s3)
  {
    return strain(s1, s2, s3, 0., 0., 0.);
  }

  // Hosford: [(|s1 - s2|^a + |s2 - s3|^a + |s3 - s1|^a) / 2]^(1/a).
  double
  hosford(const double s1, const double s2, const double s3, const double a)
  {
    return std::pow((std::pow(std::abs(s1 - s2), a)
                     + std::pow(std::abs(s2 - s3), a)
                     + std::pow(std::abs(s3 - s1), a))
                      / 2.,
                    1. / a);
  }

  // The criterion's d sigma_bar / d sigma_22 at sigma = diag(1, q, 0).
  double
  model_n22(const Yld2004Criterion &criterion, const double q)
  {
    deepdraw::material::kelvin::Vector n;
    criterion.evaluate({{1., q, 0., 0., 0., 0.}}, n, nullptr);
    return n[1];
  }


  void
  von_mises_updates()
  {
    std::cout << "(a) a = 2 against Hill'48 von Mises" << std::endl;
    for (const double k : {0., 1500.})
    {
      MaterialParameters hill = von_mises_parameters();
      hill.prager_modulus     = k;
      MaterialParameters yld  = isotropic_yld2004(2.);
      yld.prager_modulus      = k;
      const ElastoPlasticity reference(hill), material(yld);
      MaterialPointState     prestressed;
      prestressed.stress      = strain(120., -40., 30., 50., -20., 10.);
      prestressed.back_stress = strain(20., -15., -5., 10., 3., -6.);
      prestressed.equivalent_plastic_strain = 0.05;
      double worst_state = 0., worst_tangent = 0.;
      for (const auto &increment :
           {strain(3e-3, -1e-3, -1e-3, 0., 0., 0.),
            strain(2e-3, 1e-3, -4e-3, 1.5e-3, -1e-3, 0.5e-3),
            strain(0.08, -0.05, 0.01, 0.03, 0.02, -0.04),
            strain(0.4, -0.1, -0.25, -0.2, 0.15, 0.3)})
        for (const auto &old_state : {MaterialPointState(), prestressed})
        {
          MaterialPointState    a, b;
          SymmetricTensor<4, 3> Ta, Tb;
          bool                  pa, pb;
          const bool ok = reference.update(old_state, increment, a, Ta, pa)
                          && material.update(old_state, increment, b, Tb, pb)
                          && pa && pb;
          if (!ok)
            worst_state = 1e300;
          worst_state = std::max(
            {worst_state,
             (a.stress - b.stress).norm() / a.stress.norm(),
             (a.back_stress - b.back_stress).norm() / a.stress.norm(),
             std::abs(a.equivalent_plastic_strain - b.equivalent_plastic_strain)
               / a.equivalent_plastic_strain});
          worst_tangent = std::max(worst_tangent, (Ta - Tb).norm() / Ta.norm());
        }
      const std::string label = " (Prager k = " + std::to_string(int(k)) + ")";
      deepdraw_test::check_close("  8 plastic updates, state" + label,
                                 worst_state,
                                 0.,
                                 1e-9);
      deepdraw_test::check_close("  8 plastic updates, tangent" + label,
                                 worst_tangent,
                                 0.,
                                 1e-9);
    }
  }


  void
  von_mises_limit()
  {
    const MaterialParameters p = isotropic_yld2004(2.);
    const ElastoPlasticity   material(p);
    double                   worst = 0.;
    for (const auto &xi : {strain(120., -40., 30., 50., -20., 10.),
                           strain(1., 0., 0., 0., 0., 0.),
                           strain(0., 0., 0., 0., 1., 0.),
                           strain(-3., 7., 2., 0., 0., 5.)})
      worst = std::max(worst,
                       std::abs(material.equivalent_stress(xi)
                                - std::sqrt(1.5) * deviator(xi).norm())
                         / (std::sqrt(1.5) * deviator(xi).norm()));
    deepdraw_test::check_close("sigma_bar = sqrt(3/2) |dev xi|, 4 stresses",
                               worst,
                               0.,
                               1e-14);
    von_mises_updates();

    MaterialParameters flat = p;
    flat.swift_exponent     = 0.; // Y = C
    flat.swift_coefficient  = 250.;
    const ElastoPlasticity perfectly_plastic(flat);
    for (const double angle : {0., 30., 45., 90.})
    {
      const UniaxialFlow flow = uniaxial_flow(perfectly_plastic, angle);
      const std::string  label
        = "  uniaxial " + std::to_string(int(angle)) + " deg: ";
      deepdraw_test::check_true(label + "converged, plastic", flow.ok);
      deepdraw_test::check_relative(label + "yield stress / Y",
                                    flow.stress / 250.,
                                    1.,
                                    1e-8);
      deepdraw_test::check_relative(label + "r", flow.r(), 1., 1e-8);
    }
  }


  void
  hosford_limit()
  {
    std::cout << "(b) a = 8: Hosford" << std::endl;
    const double           a = 8.;
    const ElastoPlasticity material(isotropic_yld2004(a));
    const auto            &criterion = material.yld2004_criterion();
    // Principal stresses (1, -0.3, 0.45) turned by Q: Hosford of them.
    Tensor<2, 3> Q = load_axes(37.);
    Q              = Q * transpose(load_axes(-20.)); // a second in-plane turn
    double worst   = 0.;
    for (const auto &[s1, s2, s3] : {std::array<double, 3>{{1., -0.3, 0.45}},
                                     std::array<double, 3>{{2., 2., -1.}},
                                     std::array<double, 3>{{0.2, 0.7, 0.7}}})
    {
      const double expected = hosford(s1, s2, s3, a);
      for (const auto &xi :
           {diagonal(s1, s2, s3), rotate(Q, diagonal(s1, s2, s3))})
        worst = std::max(worst,
                         std::abs(material.equivalent_stress(xi) - expected)
                           / expected);
    }
    deepdraw_test::check_close("  sigma_bar = Hosford, 6 stresses",
                               worst,
                               0.,
                               1e-14);

    // Plane strain (d eps_22 = 0) under sigma = diag(1, q, 0).
    const auto dhosford = [&](const double q)
    {
      const double h = 1e-6;
      return hosford(1., q + h, 0., a) - hosford(1., q - h, 0., a);
    };
    const double q_independent = bisect(dhosford, 0., 1.);
    const double ratio         = 1. / hosford(1., q_independent, 0., a);
    const double q_model
      = bisect([&](const double q) { return model_n22(criterion, q); }, 0., 1.);
    const double ratio_model
      = 1. / material.equivalent_stress(diagonal(1., q_model, 0.));
    std::cout << "  plane strain at sigma_22 / sigma_11 = " << q_model
              << " (independent " << q_independent << ")" << std::endl;
    deepdraw_test::check_close("  plane strain / uniaxial, independent",
                               ratio,
                               1.0894,
                               5e-5);
    deepdraw_test::check_relative("  plane strain / uniaxial, criterion",
                                  ratio_model,
                                  ratio,
                                  1e-10);
    deepdraw_test::check_relative(
      "  equibiaxial / uniaxial",
      1. / material.equivalent_stress(diagonal(1., 1., 0.)),
      1.,
      1e-14);
  }
} // namespace


int
main()
{
  std::cout << "(a) a = 2: von Mises" << std::endl;
  von_mises_limit();
  hosford_limit();
  return deepdraw_test::summary();
}
