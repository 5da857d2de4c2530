// Gap vector ĝ = g_N n + g_T of one node against a rigid tool
// (doc/theory_contact.md): values on a plane against the analytic expressions,
// distances on a sphere and a torus against their closed forms, and the full
// linearisation (moving foot point and turning normal) against central
// differences with a fresh closest-point projection for every perturbed Δu and
// tool position z.
#include "contact/contact_test_tools.h"

#include <deepdraw/contact/contact_pair_kinematics.h>
#include <iostream>
#include <memory>

using namespace deepdraw::contact;
using namespace contact_test;
using deepdraw_test::check_close;
using deepdraw_test::check_true;

namespace
{
  void
  plane_values()
  {
    std::cout << "plane" << std::endl;
    for (unsigned int k = 0; k < 3; ++k)
    {
      const Tensor<1, 3> n  = random_unit_vector();
      const Tensor<1, 3> t1 = random_tangent(n);
      const Tensor<1, 3> t2 = cross_product_3d(n, t1);
      const Point<3>     p0(random_vector(5.));
      const Tensor<1, 3> a         = random_unit_vector();
      const Tensor<1, 3> tool_step = 0.04 * a;
      const Point<3>     X_t       = p0 + 0.3 * t1 - 0.2 * t2 + 0.05 * n;
      const Tensor<1, 3> du        = random_vector(0.1);
      const Point<3>     x         = X_t + du;
      // The plane now passes through p0 + tool_step.
      const double                         distance = (x - p0 - tool_step) * n;
      deepdraw::geometry::ProjectionResult cp;
      cp.foot      = x - distance * n;
      cp.normal    = n;
      cp.tangent_u = 2. * t1;
      cp.tangent_v = t1 + t2;
      const ContactPairKinematics kin(x, du, cp, tool_step, a);

      const Tensor<1, 3> d   = du - tool_step;
      const Tensor<1, 3> g_T = d - (d * n) * n;
      check_close("g_N = signed distance", kin.normal_gap(), distance, 1e-14);
      check_close("g_T = (I - n⊗n)(Δu - Δx̄_tool)",
                  (kin.tangential_slip() - g_T).norm(),
                  0.,
                  1e-15);
      check_close("ĝ = g_N n + g_T",
                  (kin.gap() - (distance * n + g_T)).norm(),
                  0.,
                  1e-15);
      check_true("plane: curvature terms formed",
                 kin.curvature_terms_included());
      check_close("plane: dĝ/dΔu = I",
                  (kin.dgap_ddisplacement() - identity()).norm(),
                  0.,
                  1e-15);
      check_close("plane: dĝ/dz = -a",
                  (kin.dgap_dtool_position() + a).norm(),
                  0.,
                  1e-15);
      check_close("plane: dn/dΔu = 0",
                  kin.dnormal_ddisplacement().norm(),
                  0.,
                  0.);

      // Without tangents the full linearisation falls back to frozen.
      deepdraw::geometry::ProjectionResult bare;
      bare.foot   = cp.foot;
      bare.normal = n;
      const ContactPairKinematics fallback(x, du, bare, tool_step, a);
      check_true("no tangents: frozen fallback",
                 !fallback.curvature_terms_included()
                   && (fallback.dgap_ddisplacement() - identity()).norm()
                        == 0.);
    }
  }


  struct Case
  {
    std::string              name;
    std::shared_ptr<Surface> surface;
    double                   u0, v0, offset; // node at x̄(u0, v0) + offset n
    double                   expected_distance_of_x_t; // closed form, or NaN
  };


  void
  curved(const Case &c)
  {
    std::cout << c.name << std::endl;
    const Surface &s = *c.surface;
    Tensor<1, 3>   S[6];
    s.evaluate(c.u0, c.v0, S);
    Tensor<1, 3> n0 = cross_product_3d(S[1], S[2]);
    n0 *= s.orientation / n0.norm();
    const Point<3>     X_t(S[0] + c.offset * n0 + 0.02 * S[1] / S[1].norm());
    const Tensor<1, 3> a   = random_unit_vector();
    const double       z_t = 0.;
    const Tensor<1, 3> du0 = random_vector(0.05);
    const double       z0  = 0.03;

    // Projection at the start of the increment: g_N against closed forms.
    {
      double                      u = c.u0, v = c.v0;
      const auto                  cp = project(s, X_t, Tensor<1, 3>(), u, v);
      const ContactPairKinematics kin(X_t, Tensor<1, 3>(), cp, Tensor<1, 3>());
      if (std::isfinite(c.expected_distance_of_x_t))
        check_close("g_N = closed-form distance",
                    kin.normal_gap(),
                    c.expected_distance_of_x_t,
                    1e-13);
      else
        check_close("g_N = offset", kin.normal_gap(), c.offset, 1e-3);
    }

    auto kinematics
      = [&](const Tensor<1, 3> &du, const double z, const Linearisation lin)
    {
      double     u = c.u0, v = c.v0;
      const auto cp = project(s, X_t + du, z * a, u, v);
      return ContactPairKinematics(X_t + du, du, cp, (z - z_t) * a, a, lin);
    };
    const auto kin    = kinematics(du0, z0, Linearisation::full);
    const auto frozen = kinematics(du0, z0, Linearisation::frozen_normal);
    std::cout << "  g_N = " << kin.normal_gap()
              << ", |g_T| = " << kin.tangential_slip().norm() << std::endl;
    check_true("curvature terms formed", kin.curvature_terms_included());

    const double h = 1e-6;
    using V        = const Tensor<1, 3> &;
    check_block(
      "dĝ/dΔu",
      kin.dgap_ddisplacement(),
      fd_jacobian([&](V x)
                  { return kinematics(x, z0, Linearisation::full).gap(); },
                  du0,
                  h));
    check_block(
      "dĝ/dz",
      kin.dgap_dtool_position(),
      fd_derivative([&](double x)
                    { return kinematics(du0, x, Linearisation::full).gap(); },
                    z0,
                    h));
    check_block(
      "dn/dΔu",
      kin.dnormal_ddisplacement(),
      fd_jacobian([&](V x)
                  { return kinematics(x, z0, Linearisation::full).normal(); },
                  du0,
                  h));
    check_block("dn/dz",
                kin.dnormal_dtool_position(),
                fd_derivative(
                  [&](double x)
                  { return kinematics(du0, x, Linearisation::full).normal(); },
                  z0,
                  h));

    // Frozen normal and foot point: the documented simple forms, and they
    // do differ from the exact derivative on a curved tool.
    check_close("frozen: dĝ/dΔu = I",
                (frozen.dgap_ddisplacement() - identity()).norm(),
                0.,
                0.);
    check_close("frozen: dĝ/dz = -a",
                (frozen.dgap_dtool_position() + a).norm(),
                0.,
                0.);
    check_close("frozen: dn = 0",
                frozen.dnormal_ddisplacement().norm()
                  + frozen.dnormal_dtool_position().norm(),
                0.,
                0.);
    check_true("frozen: same ĝ", (frozen.gap() - kin.gap()).norm() == 0.);
    const double difference
      = (frozen.dgap_ddisplacement() - kin.dgap_ddisplacement()).norm();
    std::cout << "  |dĝ/dΔu (full) - I| = " << difference << std::endl;
    check_true("curvature terms are not negligible here", difference > 1e-3);
  }
} // namespace

int
main()
{
  plane_values();

  const Point<3> c(1., -2., 0.5);
  // Torus (R 10, ρ 3, outward normal, a punch radius) on its outer, convex
  // side and on its inner, saddle side; distance sqrt((ρ_xy − R)² + z²) − ρ.
  auto torus_distance = [&](const double u, const double v, const double g)
  {
    auto         torus = Torus(c, 10., 3., 1.);
    Tensor<1, 3> S[6];
    torus.evaluate(u, v, S);
    Tensor<1, 3> n = cross_product_3d(S[1], S[2]);
    n /= n.norm();
    const Tensor<1, 3> y = S[0] + g * n + 0.02 * S[1] / S[1].norm() - c;
    return std::sqrt(std::pow(std::hypot(y[0], y[1]) - 10., 2) + y[2] * y[2])
           - 3.;
  };
  // Sphere (R 8) seen from inside, normal towards the centre (a die cup):
  // g_N = R − |x − c|.
  auto sphere_distance = [&](const double u, const double v, const double g)
  {
    auto         sphere = Sphere(c, 8., -1.);
    Tensor<1, 3> S[6];
    sphere.evaluate(u, v, S);
    Tensor<1, 3> n = -cross_product_3d(S[1], S[2]);
    n /= n.norm();
    return 8. - (S[0] + g * n + 0.02 * S[1] / S[1].norm() - c).norm();
  };

  const std::vector<Case> cases
    = {{"torus outside, open",
        std::make_shared<Torus>(c, 10., 3., 1.),
        0.4,
        0.7,
        0.2,
        torus_distance(0.4, 0.7, 0.2)},
       {"torus outside, penetrated",
        std::make_shared<Torus>(c, 10., 3., 1.),
        1.1,
        -0.5,
        -0.15,
        torus_distance(1.1, -0.5, -0.15)},
       {"torus saddle side",
        std::make_shared<Torus>(c, 10., 3., 1.),
        -0.3,
        2.6,
        -0.1,
        torus_distance(-0.3, 2.6, -0.1)},
       {"sphere from inside, open",
        std::make_shared<Sphere>(c, 8., -1.),
        0.3,
        0.4,
        0.1,
        sphere_distance(0.3, 0.4, 0.1)},
       {"sphere from inside, penetrated",
        std::make_shared<Sphere>(c, 8., -1.),
        -0.7,
        -0.2,
        -0.2,
        sphere_distance(-0.7, -0.2, -0.2)},
       {"skew paraboloid, open",
        std::make_shared<SkewParaboloid>(),
        0.5,
        -0.3,
        0.15,
        std::nan("")},
       {"skew paraboloid (flipped normal), penetrated",
        []
        {
          auto p         = std::make_shared<SkewParaboloid>();
          p->orientation = -1.;
          return p;
        }(),
        -0.4,
        0.6,
        -0.1,
        std::nan("")}};
  for (const auto &c : cases)
    curved(c);

  return deepdraw_test::summary();
}
