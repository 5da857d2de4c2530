// The three states of the Alart–Curnier law (doc/theory_contact.md) at chosen
// inputs, the complementarity conditions at solution points, and the
// independence of the solution from the augmentation parameter r: a pair (λ, ĝ)
// satisfying the contact conditions gives F_sup = 0 for every r, a pair
// violating them does not.
#include "contact/contact_test_tools.h"

#include <deepdraw/contact/alart_curnier_law.h>
#include <iostream>

using namespace deepdraw::contact;
using namespace contact_test;
using deepdraw_test::check_close;
using deepdraw_test::check_true;

namespace
{
  void
  check_vector(const std::string  &what,
               const Tensor<1, 3> &actual,
               const Tensor<1, 3> &expected,
               const double        tolerance = 1e-13)
  {
    check_close(what, (actual - expected).norm(), 0., tolerance);
  }

  void
  check_state(const std::string &what,
              ContactState       actual,
              ContactState       expected)
  {
    check_true(what + ": state " + to_string(actual) + " (expected "
                 + to_string(expected) + ")",
               actual == expected);
  }
} // namespace

int
main()
{
  const double          mu = 0.3;
  const AlartCurnierLaw law(mu);
  const double          rs[] = {1e-2, 1., 100., 1e4};

  for (unsigned int k = 0; k < 3; ++k)
  {
    const Tensor<1, 3> n = random_unit_vector();
    const Tensor<1, 3> t = random_tangent(n);
    std::cout << "normal " << n << ", tangent " << t << std::endl;

    // Chosen inputs, r = 10: λ̂ = λ − 10 ĝ.
    {
      const double r = 10.;
      // Gap open by 0.2 and no force: λ̂_N = −2.
      auto res = law.evaluate(Tensor<1, 3>(), 0.2 * n + 0.05 * t, n, r);
      check_state("open, free node", res.state, ContactState::open);
      check_vector("open: P = 0", res.force, Tensor<1, 3>());
      check_vector("open: F_sup = 0 at λ = 0",
                   res.constraint_residual,
                   Tensor<1, 3>());
      // Open with a force left: F_sup = λ/r asks for λ = 0.
      const Tensor<1, 3> lambda = 1. * n + 0.5 * t;
      res                       = law.evaluate(lambda, 0.2 * n, n, r);
      check_state("open, λ ≠ 0", res.state, ContactState::open);
      check_vector("open: F_sup = λ/r", res.constraint_residual, lambda / r);
      // At the kink λ̂_N = 0 the contact is active, only λ̂_N < 0 is open
      // (decisions.md D17). The inputs make λ̂_N exactly 0: with r = 8,
      // λ = 2 n, ĝ = 0.25 n every product is a power-of-two scaling, so
      // λ̂ = 2 n − 8 (0.25 n) = 0 component by component, without rounding
      // (with r = 10, ĝ = 0.2 n it came out as about −2e-16, i.e. open).
      {
        const double r_kink = 8.;
        res                 = law.evaluate(2. * n, 0.25 * n, n, r_kink);
        check_true("λ̂_N = 0 exactly (inputs exact)",
                   res.augmented_force * n == 0.
                     && res.augmented_force.norm() == 0.);
        check_state("λ̂_N = 0, λ̂_T = 0: active", res.state, ContactState::stick);
        check_vector("λ̂_N = 0: P = 0", res.force, Tensor<1, 3>());
        check_vector("λ̂_N = 0: F_sup = λ/r",
                     res.constraint_residual,
                     (2. / r_kink) * n);
        // The active branch also in the Newton matrix: ∂P/∂λ = I (open: 0).
        check_vector("λ̂_N = 0: ∂P/∂λ n = n (active branch)",
                     Tensor<1, 3>(res.dforce_dmultiplier * n),
                     n);
        // With a tangential part (axis-aligned so λ̂_T is exact too):
        // |λ̂_T| > μ λ̂_N = 0 gives slip, still active, P = λ̂_N (n + μ t) = 0.
        const Tensor<1, 3> ez({0., 0., 1.});
        const Tensor<1, 3> ex({1., 0., 0.});
        res = law.evaluate(2. * ez + 0.5 * ex, 0.25 * ez, ez, r_kink);
        check_true("λ̂_N = 0 exactly, λ̂_T = 0.5 e_x (inputs exact)",
                   res.augmented_force * ez == 0.
                     && res.augmented_force == 0.5 * ex);
        check_state("λ̂_N = 0, λ̂_T ≠ 0: active", res.state, ContactState::slip);
        check_vector("λ̂_N = 0, λ̂_T ≠ 0: P = 0", res.force, Tensor<1, 3>());
        check_vector("λ̂_N = 0, λ̂_T ≠ 0: ∂P/∂λ n = n + μ t (active branch)",
                     Tensor<1, 3>(res.dforce_dmultiplier * ez),
                     ez + mu * ex);
      }

      // Penetration 0.1, no friction demand: λ̂ = 1 n + 0.2 t, 0.2 <= 0.3.
      res = law.evaluate(Tensor<1, 3>(), -0.1 * n - 0.02 * t, n, r);
      check_state("stick inside the cone", res.state, ContactState::stick);
      check_vector("stick: P = λ̂", res.force, 1. * n + 0.2 * t);
      check_vector("stick: F_sup = ĝ",
                   res.constraint_residual,
                   -0.1 * n - 0.02 * t);

      // Outside the cone: λ̂ = 1 n + 0.5 t, |λ̂_T| = 0.5 > 0.3.
      res = law.evaluate(Tensor<1, 3>(), -0.1 * n - 0.05 * t, n, r);
      check_state("slip outside the cone", res.state, ContactState::slip);
      check_vector("slip: P = λ̂_N (n + μ t)", res.force, 1. * n + mu * t);
      check_close("slip: |P_T| = μ P_N",
                  (res.force - (res.force * n) * n).norm(),
                  mu * (res.force * n),
                  1e-14);
    }

    // Solution points: F_sup = 0 for every r.
    for (const double r : rs)
    {
      const std::string at = " (r = " + std::to_string(r) + ")";
      // No contact: g_N > 0, λ = 0.
      auto res = law.evaluate(Tensor<1, 3>(), 0.3 * n + 0.1 * t, n, r);
      check_state("solution, open" + at, res.state, ContactState::open);
      check_vector("open solution: F_sup = 0" + at,
                   res.constraint_residual,
                   Tensor<1, 3>());

      // Stick: ĝ = 0, λ inside the cone (|λ_T| = 1 < 0.3 × 5).
      const Tensor<1, 3> lambda_stick = 5. * n + 1. * t;
      res = law.evaluate(lambda_stick, Tensor<1, 3>(), n, r);
      check_state("solution, stick" + at, res.state, ContactState::stick);
      check_vector("stick solution: F_sup = 0" + at,
                   res.constraint_residual,
                   Tensor<1, 3>());
      check_vector("stick solution: P = λ" + at,
                   res.force,
                   lambda_stick,
                   1e-12);

      // Slip along t: g_N = 0, g_T = 0.1 t, λ_T = −μ λ_N t (opposes the
      // slip of the node relative to the tool).
      const Tensor<1, 3> lambda_slip = 5. * n - mu * 5. * t;
      res                            = law.evaluate(lambda_slip, 0.1 * t, n, r);
      check_state("solution, slip" + at, res.state, ContactState::slip);
      check_vector("slip solution: F_sup = 0" + at,
                   res.constraint_residual,
                   Tensor<1, 3>(),
                   1e-12 * (1. + 1. / r));

      // Violations: friction in the direction of the slip; a closed gap
      // with a tensile force; a stuck node that moved. F_sup ≠ 0.
      res = law.evaluate(5. * n + mu * 5. * t, 0.1 * t, n, r);
      check_true("friction along the slip: F_sup ≠ 0" + at,
                 res.constraint_residual.norm() > 1e-8);
      res = law.evaluate(-1. * n, Tensor<1, 3>(), n, r);
      check_true("tensile contact force: F_sup ≠ 0" + at,
                 res.constraint_residual.norm() > 1e-8);
      res = law.evaluate(5. * n, -0.01 * n, n, r);
      check_true("penetrated node: F_sup ≠ 0" + at,
                 res.constraint_residual.norm() > 1e-8);
      res = law.evaluate(5. * n - 0.5 * mu * 5. * t, 0.1 * t, n, r);
      check_true("slip below the limit: F_sup ≠ 0" + at,
                 res.constraint_residual.norm() > 1e-8);
    }

    // Frictionless: a closed node is `slip`, P = λ̂_N n, also for λ̂_T = 0.
    {
      const AlartCurnierLaw frictionless(0.);
      auto res = frictionless.evaluate(2. * n + 3. * t, -0.1 * n, n, 10.);
      check_state("μ = 0, closed", res.state, ContactState::slip);
      check_vector("μ = 0: P = λ̂_N n", res.force, 3. * n);
      res = frictionless.evaluate(2. * n, -0.1 * n, n, 10.);
      check_state("μ = 0, λ̂_T = 0", res.state, ContactState::slip);
      check_vector("μ = 0, λ̂_T = 0: P = λ̂_N n", res.force, 3. * n);
      check_vector("μ = 0, λ̂_T = 0: ∂P/∂λ = n⊗n",
                   Tensor<1, 3>(res.dforce_dmultiplier * t),
                   Tensor<1, 3>());
      check_true("μ = 0, λ̂_T = 0: finite derivatives",
                 std::isfinite(res.dforce_dnormal.norm()));
      res = frictionless.evaluate(3. * n - 1. * t, 0.1 * t, n, 10.);
      check_vector("μ = 0 solution with λ_T ≠ 0: F_sup = λ_T/r",
                   res.constraint_residual,
                   -0.1 * t);
      res = frictionless.evaluate(3. * n, 0.1 * t, n, 10.);
      check_vector("μ = 0 solution, free sliding: F_sup = 0",
                   res.constraint_residual,
                   Tensor<1, 3>());
    }
  }
  return deepdraw_test::summary();
}
