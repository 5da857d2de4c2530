// Every generalised derivative of the Alart–Curnier law (∂P/∂λ, ∂P/∂ĝ,
// ∂P/∂n, ∂F_sup/∂λ, ∂F_sup/∂ĝ, ∂F_sup/∂n) against central differences, at
// points well inside each state, for random normals, several r and μ,
// including μ = 0; plus the closed forms of the open and stick states.
#include "contact/contact_test_tools.h"

#include <deepdraw/contact/alart_curnier_law.h>
#include <iostream>

using namespace deepdraw::contact;
using namespace contact_test;
using deepdraw_test::check_close;
using deepdraw_test::check_true;

namespace
{
  // λ̂ = λ̂_N n + |λ̂_T| t, well inside the requested state.
  Tensor<1, 3>
  augmented_force_inside(const ContactState  state,
                         const double        mu,
                         const Tensor<1, 3> &n,
                         const Tensor<1, 3> &t)
  {
    switch (state)
    {
      case ContactState::open:
        return -3. * n + 2. * t;
      case ContactState::stick:
        return 5. * n + 0.5 * mu * 5. * t;
      case ContactState::slip:
      default:
        return 5. * n + (2. * mu * 5. + 1.) * t;
    }
  }
} // namespace

int
main()
{
  const ContactState states[]
    = {ContactState::open, ContactState::stick, ContactState::slip};
  for (const double mu : {0.162, 0.6, 0.})
    for (const ContactState state : states)
    {
      if (mu == 0. && state == ContactState::stick)
        continue; // no stick without friction
      const AlartCurnierLaw law(mu);
      for (const double r : {1., 250.})
        for (unsigned int k = 0; k < 3; ++k)
        {
          const Tensor<1, 3> n   = random_unit_vector();
          const Tensor<1, 3> t   = random_tangent(n);
          const Tensor<1, 3> gap = random_vector(0.1);
          const Tensor<1, 3> lambda
            = augmented_force_inside(state, mu, n, t) + r * gap;
          const auto        res  = law.evaluate(lambda, gap, n, r);
          const std::string what = std::string(to_string(state)) + ", mu "
                                   + std::to_string(mu) + ", r "
                                   + std::to_string(r) + ": ";
          std::cout << what << "n = " << n << std::endl;
          check_true(what + "state", res.state == state);

          auto P = [&](const Tensor<1, 3> &l,
                       const Tensor<1, 3> &g,
                       const Tensor<1, 3> &m)
          { return law.evaluate(l, g, m, r).force; };
          auto F = [&](const Tensor<1, 3> &l,
                       const Tensor<1, 3> &g,
                       const Tensor<1, 3> &m)
          { return law.evaluate(l, g, m, r).constraint_residual; };
          // Steps: λ ~ 5 + r|ĝ|, ĝ ~ 0.1 (r ĝ ~ λ), n ~ 1.
          const double hl = 1e-5 * (1. + lambda.norm());
          const double hg = hl / r;
          const double hn = 1e-6;
          using V         = const Tensor<1, 3> &;
          check_block(what + "dP/dλ",
                      res.dforce_dmultiplier,
                      fd_jacobian([&](V x) { return P(x, gap, n); },
                                  lambda,
                                  hl));
          check_block(what + "dP/dĝ",
                      res.dforce_dgap,
                      fd_jacobian([&](V x) { return P(lambda, x, n); },
                                  gap,
                                  hg));
          check_block(what + "dP/dn",
                      res.dforce_dnormal,
                      fd_jacobian([&](V x) { return P(lambda, gap, x); },
                                  n,
                                  hn));
          check_block(what + "dF_sup/dλ",
                      res.dconstraint_dmultiplier,
                      fd_jacobian([&](V x) { return F(x, gap, n); },
                                  lambda,
                                  hl));
          check_block(what + "dF_sup/dĝ",
                      res.dconstraint_dgap,
                      fd_jacobian([&](V x) { return F(lambda, x, n); },
                                  gap,
                                  hg));
          check_block(what + "dF_sup/dn",
                      res.dconstraint_dnormal,
                      fd_jacobian([&](V x) { return F(lambda, gap, x); },
                                  n,
                                  hn));

          // Closed forms (doc/theory_contact.md).
          const Tensor<2, 3> I = identity();
          if (state == ContactState::open)
          {
            check_close(what + "open: P = 0", res.force.norm(), 0., 0.);
            check_close(what + "open: dF_sup/dλ = I/r",
                        (res.dconstraint_dmultiplier - I / r).norm(),
                        0.,
                        1e-15);
            check_close(what + "open: dP/dĝ = 0",
                        res.dforce_dgap.norm(),
                        0.,
                        0.);
          }
          else if (state == ContactState::stick)
          {
            check_close(what + "stick: dP/dλ = I",
                        (res.dforce_dmultiplier - I).norm(),
                        0.,
                        1e-15);
            check_close(what + "stick: dP/dĝ = -r I",
                        (res.dforce_dgap + r * I).norm(),
                        0.,
                        1e-12);
            check_close(what + "stick: dF_sup/dĝ = I",
                        (res.dconstraint_dgap - I).norm(),
                        0.,
                        1e-15);
            check_close(what + "stick: dF_sup/dλ = 0",
                        res.dconstraint_dmultiplier.norm(),
                        0.,
                        1e-15);
          }
          else
          {
            // Slip: a normal variation of λ̂ scales the whole force
            // P along n + μ t; a variation along t changes nothing.
            const Tensor<1, 3> a   = lambda - r * gap;
            const Tensor<1, 3> a_T = a - (a * n) * n;
            const Tensor<1, 3> dir = a_T / a_T.norm();
            check_close(what + "slip: dP/dλ n = n + μ t",
                        (res.dforce_dmultiplier * n - (n + mu * dir)).norm(),
                        0.,
                        1e-13);
            check_close(what + "slip: dP/dλ t = 0",
                        (res.dforce_dmultiplier * dir).norm(),
                        0.,
                        1e-13);
          }
        }
    }

  // μ = 0 with λ̂_T = 0 exactly: P = λ̂_N n is smooth there.
  {
    const AlartCurnierLaw law(0.);
    const Tensor<1, 3>    n      = random_unit_vector();
    const Tensor<1, 3>    lambda = 4. * n, gap = -0.05 * n;
    const double          r   = 20.;
    const auto            res = law.evaluate(lambda, gap, n, r);
    using V                   = const Tensor<1, 3> &;
    check_true("mu 0, λ̂_T = 0: slip", res.state == ContactState::slip);
    check_block("mu 0, λ̂_T = 0: dP/dλ",
                res.dforce_dmultiplier,
                fd_jacobian([&](V x)
                            { return law.evaluate(x, gap, n, r).force; },
                            lambda,
                            1e-5));
    check_block("mu 0, λ̂_T = 0: dP/dn",
                res.dforce_dnormal,
                fd_jacobian([&](V x)
                            { return law.evaluate(lambda, gap, x, r).force; },
                            n,
                            1e-6));
    check_block(
      "mu 0, λ̂_T = 0: dF_sup/dĝ",
      res.dconstraint_dgap,
      fd_jacobian([&](V x)
                  { return law.evaluate(lambda, x, n, r).constraint_residual; },
                  gap,
                  1e-6));
  }
  return deepdraw_test::summary();
}
