// The consistent tangent of ElastoPlasticity::update equals a central finite
// difference of the stress update (doc/theory_material.md: the global Newton's
// quadratic convergence relies on it). Elastic, plastic, kinematic hardening,
// perfect plasticity, several multiaxial and large increments.
//
// Tolerance 1e-6 of max|T|: with step h = 1e-5 max(|d_eps|, 1e-4) the
// truncation error is ~ (h/|d_eps|)^2 ~ 1e-10 and the round-off
// ~ 1e-16 |sigma| / h / |T| < 1e-8; a wrong term (e.g. a frozen gamma) gives
// errors of order 1e-2 .. 1.
#include "../test_utilities.h"
#include "material_test_tools.h"

#include <deepdraw/material/elasto_plasticity.h>

using namespace material_test;

int
main()
{
  std::vector<std::pair<std::string, MaterialParameters>> materials;
  materials.emplace_back("NUMISHEET'93 aluminium", MaterialParameters());
  {
    MaterialParameters p;
    p.prager_modulus = 3000.;
    materials.emplace_back("aluminium + Prager k = 3000 MPa", p);
  }
  {
    MaterialParameters p = von_mises_parameters();
    p.prager_modulus     = 1000.;
    materials.emplace_back("von Mises + Prager", p);
  }
  {
    // Strongly anisotropic, all coefficients distinct, perfectly plastic.
    MaterialParameters p;
    p.hill_F            = 0.2;
    p.hill_G            = 0.9;
    p.hill_H            = 0.35;
    p.hill_L            = 1.1;
    p.hill_M            = 2.3;
    p.hill_N            = 1.6;
    p.swift_exponent    = 0.;
    p.swift_coefficient = 150.;
    materials.emplace_back("anisotropic, perfectly plastic", p);
  }
  {
    MaterialParameters p;
    p.hill_F         = 0.2;
    p.hill_G         = 0.9;
    p.hill_H         = 0.35;
    p.hill_L         = 1.1;
    p.hill_M         = 2.3;
    p.hill_N         = 1.6;
    p.prager_modulus = 8000.;
    p.swift_exponent = 0.6;
    materials.emplace_back("anisotropic, Swift n = 0.6 + Prager", p);
  }

  const std::vector<std::pair<std::string, SymmetricTensor<2, 3>>> increments
    = {{"tension 11", strain(2e-3, -0.7e-3, -0.6e-3, 0., 0., 0.)},
       {"multiaxial 3e-3",
        strain(3.6e-3, -1.2e-3, -0.9e-3, 1.8e-3, -0.6e-3, 0.9e-3)},
       {"shear 12 + 23", strain(1e-4, 0., -1e-4, 2e-3, 0., -1.5e-3)},
       {"multiaxial 1e-2", strain(-4e-3, 9e-3, -3e-3, -5e-3, 7e-3, 2e-3)},
       {"large 0.1", strain(0.1, -0.03, -0.06, 0.04, -0.02, 0.05)},
       {"large 0.5", strain(-0.2, 0.5, -0.25, 0.3, 0.1, -0.2)}};

  for (const auto &[material_name, parameters] : materials)
  {
    std::cout << material_name << std::endl;
    check_tangents(ElastoPlasticity(parameters), increments);
  }
  check_nan_increment_fails(ElastoPlasticity(MaterialParameters()));
  return deepdraw_test::summary();
}
