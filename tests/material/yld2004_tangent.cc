// The derivatives of Yld2004-18p and the consistent tangent of the general
// return mapping (doc/theory_material.md §3.2, §4) against central finite
// differences.
//
// (a) Gradient and Hessian of sigma_bar against differences of sigma_bar and
//     of the gradient (step 1e-6 |xi|): AA2090-T3, a non-integer exponent,
//     and the isotropic coefficients at stresses with two equal principal
//     values (uniaxial, equibiaxial: the limit branch of the spin terms)
//     and with two principal values 1e-9 apart (the expm1/log1p branch).
//     Truncation ~1e-12 and round-off ~1e-10 relative: 1e-7 is asked; the
//     naive quotient (g_i - g_k) / (lambda_i - lambda_k) at equal
//     eigenvalues gives NaN, and dropping the spin terms errors of 0.1-1.
// (b) The tangent of ElastoPlasticity::update against differences of the
//     update (material_test::tangent_error, step 1e-5 |d_eps|), tolerance
//     1e-6 of max |T| as for Hill'48: elastic and plastic steps, virgin and
//     pre-deformed, with Prager, perfectly plastic, increments up to 0.5,
//     and the equal-eigenvalue states.
#include "../test_utilities.h"
#include "material_test_tools.h"

#include <deepdraw/material/elasto_plasticity.h>

using namespace material_test;
namespace kelvin = deepdraw::material::kelvin;

namespace
{
  MaterialParameters
  with_coefficients(const double c, const double a)
  {
    MaterialParameters p;
    p.yield_criterion = YieldCriterion::yld2004_18p;
    p.yld2004_c1.fill(c);
    p.yld2004_c2.fill(c);
    p.yld2004_exponent = a;
    return p;
  }

  // max relative error of the gradient and of the Hessian at xi.
  std::pair<double, double>
  derivative_errors(const deepdraw::material::Yld2004Criterion &criterion,
                    const SymmetricTensor<2, 3>                &xi_tensor)
  {
    const kelvin::Vector xi = kelvin::from_tensor(xi_tensor);
    kelvin::Vector       n, n_plus, n_minus;
    kelvin::Matrix       H;
    criterion.evaluate(xi, n, &H);
    const double h        = 1e-6 * std::sqrt(kelvin::dot(xi, xi));
    double gradient_error = 0., hessian_error = 0., n_max = 0., H_max = 0.;
    for (unsigned int J = 0; J < 6; ++J)
    {
      kelvin::Vector plus = xi, minus = xi;
      plus[J] += h;
      minus[J] -= h;
      const double f_plus  = criterion.evaluate(plus, n_plus, nullptr);
      const double f_minus = criterion.evaluate(minus, n_minus, nullptr);
      gradient_error       = std::max(gradient_error,
                                std::abs((f_plus - f_minus) / (2. * h) - n[J]));
      n_max                = std::max(n_max, std::abs(n[J]));
      for (unsigned int I = 0; I < 6; ++I)
      {
        hessian_error
          = std::max(hessian_error,
                     std::abs((n_plus[I] - n_minus[I]) / (2. * h) - H[I][J]));
        H_max = std::max(H_max, std::abs(H[I][J]));
      }
    }
    return {gradient_error / n_max, hessian_error / H_max};
  }


  void
  criterion_derivatives()
  {
    std::cout << "(a) gradient and Hessian of sigma_bar" << std::endl;
    const std::vector<std::pair<std::string, MaterialParameters>> criteria
      = {{"AA2090-T3", aa2090_t3_parameters()},
         {"AA2090-T3 coefficients, a = 5.7",
          []
          {
            MaterialParameters p = aa2090_t3_parameters();
            p.yld2004_exponent   = 5.7;
            return p;
          }()},
         {"isotropic, a = 8", with_coefficients(1., 8.)}};
    const std::vector<std::pair<std::string, SymmetricTensor<2, 3>>> stresses
      = {{"multiaxial", strain(120., -40., 30., 50., -20., 10.)},
         {"uniaxial 11", strain(200., 0., 0., 0., 0., 0.)},
         {"equibiaxial", strain(150., 150., 0., 0., 0., 0.)},
         {"uniaxial 11, s22 - s33 = 1e-9", strain(200., 1e-9, 0., 0., 0., 0.)},
         {"pure shear 12 + uniaxial 33", strain(0., 0., 80., 60., 0., 0.)}};
    for (const auto &[name, p] : criteria)
    {
      const deepdraw::material::ElastoPlasticity material(p);
      for (const auto &[stress_name, xi] : stresses)
      {
        const auto [g, H] = derivative_errors(material.yld2004_criterion(), xi);
        deepdraw_test::check_close("  " + name + ", " + stress_name
                                     + ": gradient",
                                   g,
                                   0.,
                                   1e-7);
        deepdraw_test::check_close("  " + name + ", " + stress_name
                                     + ": Hessian",
                                   H,
                                   0.,
                                   1e-7);
      }
    }
  }


  void
  update_tangents()
  {
    std::cout << "(b) consistent tangent of the update" << std::endl;
    std::vector<std::pair<std::string, MaterialParameters>> materials;
    materials.emplace_back("AA2090-T3, Swift", aa2090_t3_parameters());
    {
      MaterialParameters p = aa2090_t3_parameters();
      p.prager_modulus     = 3000.;
      materials.emplace_back("AA2090-T3, Swift + Prager 3000 MPa", p);
    }
    {
      MaterialParameters p = aa2090_t3_parameters();
      p.swift_exponent     = 0.;
      p.swift_coefficient  = 100.;
      materials.emplace_back("AA2090-T3, perfectly plastic (Y = 100 MPa)", p);
    }
    {
      MaterialParameters p = with_coefficients(1., 8.);
      p.hardening_law      = deepdraw::material::HardeningLawType::voce;
      p.prager_modulus     = 1000.;
      materials.emplace_back("isotropic a = 8, Voce + Prager", p);
    }
    const std::vector<std::pair<std::string, SymmetricTensor<2, 3>>> increments
      = {{"tension 11", strain(2e-3, -0.7e-3, -0.6e-3, 0., 0., 0.)},
         {"multiaxial 3e-3",
          strain(3.6e-3, -1.2e-3, -0.9e-3, 1.8e-3, -0.6e-3, 0.9e-3)},
         {"shear 12 + 23", strain(1e-4, 0., -1e-4, 2e-3, 0., -1.5e-3)},
         {"large 0.1", strain(0.1, -0.03, -0.06, 0.04, -0.02, 0.05)},
         {"large 0.5", strain(-0.2, 0.5, -0.25, 0.3, 0.1, -0.2)},
         // Two equal principal stresses at the converged state for the
         // isotropic criterion (axisymmetric increments from 0).
         {"uniaxial 11 (s22 = s33)", strain(3e-3, -1e-3, -1e-3, 0., 0., 0.)},
         {"equibiaxial (s11 = s22)", strain(2e-3, 2e-3, -3e-3, 0., 0., 0.)}};
    for (const auto &[name, p] : materials)
    {
      std::cout << name << std::endl;
      check_tangents(ElastoPlasticity(p), increments);
    }
  }
} // namespace


int
main()
{
  criterion_derivatives();
  update_tangents();

  check_nan_increment_fails(ElastoPlasticity(aa2090_t3_parameters()));
  return deepdraw_test::summary();
}
