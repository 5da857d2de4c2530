// The blocks of one contact pair (law ∘ kinematics) that the global Newton
// matrix needs, dP/dΔu, dP/dλ, dP/dz, dF_sup/dΔu, dF_sup/dλ, dF_sup/dz,
// against central differences of the whole chain (closest-point projection
// on a curved tool, gap, Alart–Curnier law) in each state, with and without
// friction.
#include "contact/contact_test_tools.h"

#include <deepdraw/contact/contact_pair.h>
#include <iostream>
#include <memory>

using namespace deepdraw::contact;
using namespace contact_test;
using deepdraw_test::check_close;
using deepdraw_test::check_true;

int
main()
{
  const Point<3>                        c(0.5, 1., -2.);
  std::vector<std::shared_ptr<Surface>> tools
    = {std::make_shared<Torus>(c, 10., 3., 1.),
       std::make_shared<Sphere>(c, 8., -1.)};
  const char *tool_names[]
    = {"torus (punch radius)", "sphere from inside (die cup)"};

  for (unsigned int tool = 0; tool < tools.size(); ++tool)
    for (const double mu : {0.162, 0.})
      for (const ContactState state :
           {ContactState::open, ContactState::stick, ContactState::slip})
        for (const double r : {1., 1e3})
        {
          if (mu == 0. && state == ContactState::stick)
            continue;
          const Surface        &s = *tools[tool];
          const AlartCurnierLaw law(mu);
          const double u0 = random_in(-1., 1.), v0 = random_in(-1., 1.);
          Tensor<1, 3> S[6];
          s.evaluate(u0, v0, S);
          Tensor<1, 3> n0 = cross_product_3d(S[1], S[2]);
          n0 *= s.orientation / n0.norm();
          const Point<3>     X_t(S[0] + random_in(-0.1, 0.1) * n0);
          const Tensor<1, 3> a   = random_unit_vector();
          const Tensor<1, 3> du0 = random_vector(0.05);
          const double       z0  = 0.02;

          auto kinematics =
            [&](const Tensor<1, 3> &du, const double z, const Linearisation lin)
          {
            double     u = u0, v = v0;
            const auto cp = project(s, X_t + du, z * a, u, v);
            return ContactPairKinematics(X_t + du, du, cp, z * a, a, lin);
          };
          const auto kin = kinematics(du0, z0, Linearisation::full);

          // λ with λ̂ = λ − r ĝ well inside the requested state.
          const Tensor<1, 3> n = kin.normal(), t = random_tangent(n);
          Tensor<1, 3>       target;
          if (state == ContactState::open)
            target = -3. * n + 1. * t;
          else if (state == ContactState::stick)
            target = 5. * n + 0.5 * mu * 5. * t;
          else
            target = 5. * n + (2. * mu * 5. + 1.) * t;
          const Tensor<1, 3> lambda0 = target + r * kin.gap();

          const ContactPairResult res
            = evaluate_contact_pair(law, kin, lambda0, r);
          const std::string what
            = std::string(tool_names[tool]) + ", " + to_string(state) + ", mu "
              + std::to_string(mu) + ", r " + std::to_string(r) + ": ";
          check_true(what + "state", res.state == state);

          auto evaluate = [&](const Tensor<1, 3> &du,
                              const Tensor<1, 3> &lambda,
                              const double        z)
          {
            return evaluate_contact_pair(law,
                                         kinematics(du, z, Linearisation::full),
                                         lambda,
                                         r);
          };
          using V         = const Tensor<1, 3> &;
          const double hu = 1e-6, hz = 1e-6, hl = 1e-5 * (1. + lambda0.norm());
          check_block(what + "dP/dΔu",
                      res.dforce_ddisplacement,
                      fd_jacobian([&](V x)
                                  { return evaluate(x, lambda0, z0).force; },
                                  du0,
                                  hu));
          check_block(what + "dP/dλ",
                      res.dforce_dmultiplier,
                      fd_jacobian([&](V x)
                                  { return evaluate(du0, x, z0).force; },
                                  lambda0,
                                  hl));
          check_block(what + "dP/dz",
                      res.dforce_dtool_position,
                      fd_derivative([&](double x)
                                    { return evaluate(du0, lambda0, x).force; },
                                    z0,
                                    hz));
          check_block(what + "dF_sup/dΔu",
                      res.dconstraint_ddisplacement,
                      fd_jacobian(
                        [&](V x) {
                          return evaluate(x, lambda0, z0).constraint_residual;
                        },
                        du0,
                        hu));
          check_block(
            what + "dF_sup/dλ",
            res.dconstraint_dmultiplier,
            fd_jacobian([&](V x)
                        { return evaluate(du0, x, z0).constraint_residual; },
                        lambda0,
                        hl));
          check_block(what + "dF_sup/dz",
                      res.dconstraint_dtool_position,
                      fd_derivative(
                        [&](double x) {
                          return evaluate(du0, lambda0, x).constraint_residual;
                        },
                        z0,
                        hz));

          // Output quantities.
          check_close(what + "normal force = P·n",
                      res.normal_force,
                      res.force * n,
                      1e-13);
          check_close(
            what + "|friction| <= μ P_N",
            std::max(0., res.friction_force.norm() - mu * res.normal_force),
            0.,
            1e-12);

          // The frozen-normal blocks are not the derivative on a curved
          // tool once the node is in contact (what the curvature terms
          // are for).
          if (state != ContactState::open)
          {
            const auto frozen = evaluate_contact_pair(
              law,
              kinematics(du0, z0, Linearisation::frozen_normal),
              lambda0,
              r);
            const double deviation
              = (frozen.dforce_ddisplacement - res.dforce_ddisplacement).norm()
                / res.dforce_ddisplacement.norm();
            std::cout << "  frozen-normal dP/dΔu deviates by " << deviation
                      << std::endl;
            check_true(what + "frozen normal differs from the exact dP/dΔu",
                       deviation > 1e-4);
          }
        }
  return deepdraw_test::summary();
}
