// Von Mises limit (F = G = H = 1/2, L = M = N = 3/2): the Hill return
// mapping must reproduce the classical radial return (Simo & Hughes,
// Computational Inelasticity, Box 3.1/3.2), written here independently in
// closed form: q_trial - (3G + 3k/2) dlambda = Y(epbar_n + dlambda), with
// linear hardening (perfectly plastic Swift n = 0 + Prager k, so the
// equation is linear) and with Swift hardening (scalar root by bisection to
// the last bit), with and without Prager. Stress, back stress, epbar and the
// tangent (Box 3.2: K 1(x)1 + 2G theta P_dev - 2G theta_bar n(x)n) agree to
// 1e-10 relative: both are exact up to round-off (~1e-14).
#include "../test_utilities.h"
#include "material_test_tools.h"

#include <deepdraw/material/elasto_plasticity.h>

using namespace material_test;

namespace
{
  struct Reference
  {
    MaterialPointState    state;
    SymmetricTensor<4, 3> tangent;
    bool                  plastic;
  };

  Reference
  radial_return(const MaterialParameters    &p,
                const MaterialPointState    &old_state,
                const SymmetricTensor<2, 3> &d_eps,
                const bool                   linear)
  {
    const double G = p.youngs_modulus / (2. * (1. + p.poissons_ratio));
    const double K = p.youngs_modulus / (3. * (1. - 2. * p.poissons_ratio));
    const double k = p.prager_modulus;
    const auto   Y = [&](const double e)
    {
      return p.swift_coefficient
             * std::pow(p.swift_prestrain + e, p.swift_exponent);
    };
    const auto dY = [&](const double e)
    {
      return p.swift_exponent * p.swift_coefficient
             * std::pow(p.swift_prestrain + e, p.swift_exponent - 1.);
    };
    const SymmetricTensor<2, 3> I = unit_symmetric_tensor<3>();

    Reference                   r;
    const SymmetricTensor<2, 3> stress_trial
      = old_state.stress + K * trace(d_eps) * I + 2. * G * deviator(d_eps);
    const SymmetricTensor<2, 3> s_trial
      = deviator(stress_trial - old_state.back_stress);
    const double norm_trial = s_trial.norm();
    const double q_trial    = std::sqrt(1.5) * norm_trial;
    const double epbar_n    = old_state.equivalent_plastic_strain;
    r.plastic               = q_trial > Y(epbar_n);
    if (!r.plastic)
    {
      r.state        = old_state;
      r.state.stress = stress_trial;
      r.tangent      = K * outer_product(I, I) + 2. * G * deviator_tensor<3>();
      return r;
    }
    const double a = 3. * G + 1.5 * k;
    const double dlambda
      = linear ? (q_trial - Y(0.)) / a
               : bisect([&](const double x)
                        { return q_trial - a * x - Y(epbar_n + x); },
                        0.,
                        q_trial / a);
    const SymmetricTensor<2, 3> n      = s_trial / norm_trial;
    const double                dgamma = std::sqrt(1.5) * dlambda; // |d eps^p|
    r.state.stress                     = stress_trial - 2. * G * dgamma * n;
    r.state.back_stress                = old_state.back_stress + k * dgamma * n;
    r.state.equivalent_plastic_strain  = epbar_n + dlambda;
    const double theta                 = 1. - 2. * G * dgamma / norm_trial;
    const double theta_bar
      = 1. / (1. + (dY(epbar_n + dlambda) + 1.5 * k) / (3. * G)) - (1. - theta);
    r.tangent = K * outer_product(I, I) + 2. * G * theta * deviator_tensor<3>()
                - 2. * G * theta_bar * outer_product(n, n);
    return r;
  }

  SymmetricTensor<2, 3>
  tensor(const std::vector<double> &c)
  {
    SymmetricTensor<2, 3> t;
    for (unsigned int I = 0; I < 6; ++I)
      t.access_raw_entry(I) = c[I];
    return t;
  }
} // namespace

int
main()
{
  struct Case
  {
    std::string        name;
    MaterialParameters parameters;
    bool               linear;
  };
  std::vector<Case> cases;
  {
    MaterialParameters p = von_mises_parameters();
    p.swift_exponent     = 0.; // Y = C constant
    p.swift_coefficient  = 250.;
    p.prager_modulus     = 2500.;
    cases.push_back(
      {"linear hardening (Y = 250 MPa, Prager k = 2500 MPa)", p, true});
  }
  cases.push_back({"Swift hardening", von_mises_parameters(), false});
  {
    MaterialParameters p = von_mises_parameters();
    p.prager_modulus     = 1500.;
    cases.push_back({"Swift + Prager k = 1500 MPa", p, false});
  }

  // (11, 22, 33, 12, 13, 23)
  const std::vector<std::vector<double>> increments
    = {{3e-3, -1e-3, -1e-3, 0., 0., 0.},
       {2e-3, 1e-3, -4e-3, 1.5e-3, -1e-3, 0.5e-3},
       {-1e-2, 4e-3, 3e-3, -2e-3, 6e-3, 1e-3},
       {0.08, -0.05, 0.01, 0.03, 0.02, -0.04},
       {0.4, -0.1, -0.25, -0.2, 0.15, 0.3},
       {5e-5, -2e-5, 1e-5, 1e-5, 0., 0.}}; // elastic from the virgin state

  MaterialPointState prestressed;
  prestressed.stress      = tensor({120., -40., 30., 50., -20., 10.});
  prestressed.back_stress = tensor({20., -15., -5., 10., 3., -6.});
  prestressed.equivalent_plastic_strain = 0.05;

  for (const Case &c : cases)
  {
    std::cout << c.name << std::endl;
    const ElastoPlasticity material(c.parameters);
    for (const bool from_prestressed : {false, true})
      for (const auto &increment : increments)
      {
        MaterialPointState old_state;
        if (from_prestressed)
        {
          old_state = prestressed;
          if (c.linear)
            old_state.equivalent_plastic_strain = 0.;
        }
        const SymmetricTensor<2, 3> d_eps = tensor(increment);
        const Reference             reference
          = radial_return(c.parameters, old_state, d_eps, c.linear);
        MaterialPointState    state;
        SymmetricTensor<4, 3> tangent;
        bool                  plastic;
        const bool            ok
          = material.update(old_state, d_eps, state, tangent, plastic);
        const std::string label
          = std::string(from_prestressed ? "  prestressed" : "  virgin")
            + ", |d_eps| = " + std::to_string(d_eps.norm());
        deepdraw_test::check_true(label + ": converged, plastic flag = "
                                    + (plastic ? "true" : "false"),
                                  ok && plastic == reference.plastic);
        deepdraw_test::check_close(
          label + ": |stress - reference| / |reference|",
          (state.stress - reference.state.stress).norm()
            / reference.state.stress.norm(),
          0.,
          1e-10);
        deepdraw_test::check_close(
          label + ": |X - reference| / |stress|",
          (state.back_stress - reference.state.back_stress).norm()
            / reference.state.stress.norm(),
          0.,
          1e-10);
        deepdraw_test::check_relative(label + ": epbar",
                                      state.equivalent_plastic_strain,
                                      reference.state.equivalent_plastic_strain,
                                      1e-10,
                                      1e-12);
        deepdraw_test::check_close(
          label + ": |tangent - Simo-Hughes| / |Simo-Hughes|",
          (tangent - reference.tangent).norm() / reference.tangent.norm(),
          0.,
          1e-10);
      }
  }

  // The Hill equivalent stress is exactly von Mises, and xi:M:xi = that^2.
  const ElastoPlasticity      material(von_mises_parameters());
  const SymmetricTensor<2, 3> xi = tensor({120., -40., 30., 50., -20., 10.});
  deepdraw_test::check_relative("sigma_bar = sqrt(3/2 |dev xi|^2)",
                                material.equivalent_stress(xi),
                                std::sqrt(1.5) * deviator(xi).norm(),
                                1e-14);
  deepdraw_test::check_relative("xi : M : xi = sigma_bar^2",
                                xi * material.hill48_criterion().tensor() * xi,
                                1.5 * deviator(xi).norm() * deviator(xi).norm(),
                                1e-14);
  return deepdraw_test::summary();
}
