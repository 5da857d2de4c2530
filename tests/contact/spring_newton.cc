// One node on a linear spring (stiffness k, anchored at its start position
// X_0, a height h0 above a rigid plane) loaded by a force with a normal part
// −F_N n and a tangential part F_T t. Unknowns: Δu (3) and λ (3); one
// semismooth Newton loop on
//   R_u = k Δu − P(λ, ĝ(Δu)) − F_ext = 0,   R_λ = F_sup(λ, ĝ(Δu)) = 0.
// Analytic answer, with N = F_N − k h0 > 0:
//   stick (F_T <= μN): Δu = −h0 n,                   λ = N n − F_T t;
//   slip  (F_T >  μN): Δu = −h0 n + (F_T − μN)/k t,  λ = N n − μN t;
//   open  (N < 0):     Δu = F_ext/k,                 λ = 0.
// The converged answer must not depend on r; the iterations may.
#include "contact/contact_test_tools.h"

#include <array>
#include <deepdraw/contact/contact_pair.h>
#include <functional>
#include <iostream>

using namespace deepdraw::contact;
using namespace contact_test;
using deepdraw_test::check_close;
using deepdraw_test::check_true;

namespace
{
  using Vector6 = std::array<double, 6>;
  using Matrix6 = std::array<Vector6, 6>;

  // Gaussian elimination with partial pivoting: solves J x = b.
  Vector6
  solve(Matrix6 J, Vector6 b)
  {
    for (unsigned int c = 0; c < 6; ++c)
    {
      unsigned int p = c;
      for (unsigned int i = c + 1; i < 6; ++i)
        if (std::abs(J[i][c]) > std::abs(J[p][c]))
          p = i;
      std::swap(J[c], J[p]);
      std::swap(b[c], b[p]);
      for (unsigned int i = c + 1; i < 6; ++i)
      {
        const double f = J[i][c] / J[c][c];
        for (unsigned int j = c; j < 6; ++j)
          J[i][j] -= f * J[c][j];
        b[i] -= f * b[c];
      }
    }
    Vector6 x;
    for (int i = 5; i >= 0; --i)
    {
      double s = b[i];
      for (unsigned int j = i + 1; j < 6; ++j)
        s -= J[i][j] * x[j];
      x[i] = s / J[i][i];
    }
    return x;
  }

  struct Solution
  {
    Tensor<1, 3> du, lambda;
    unsigned int iterations = 0;
    bool         converged  = false;
    ContactState state      = ContactState::open;
    double       normal_gap = 0.;
    Tensor<1, 3> normal;
  };

  // Cylinder of radius R about the axis c + s e_y, outward normal;
  // parameters (angle u from e_z towards e_x, v = y).
  deepdraw::geometry::ProjectionResult
  cylinder_closest_point(const Point<3> &c, const double R, const Point<3> &x)
  {
    const double u  = std::atan2(x[0] - c[0], x[2] - c[2]);
    const double su = std::sin(u), cu = std::cos(u);
    deepdraw::geometry::ProjectionResult cp;
    cp.foot      = c + Tensor<1, 3>({R * su, x[1] - c[1], R * cu});
    cp.normal    = Tensor<1, 3>({su, 0., cu});
    cp.tangent_u = Tensor<1, 3>({R * cu, 0., -R * su});
    cp.tangent_v = Tensor<1, 3>({0., 1., 0.});
    cp.x_uu      = Tensor<1, 3>({-R * su, 0., -R * cu});
    return cp;
  }

  // Newton from (Δu, λ) = (0, λ_start) against a fixed tool whose closest
  // point to x is closest_point(x).
  Solution
  newton(
    const AlartCurnierLaw &law,
    const double           r,
    const double           k,
    const Point<3>        &X_0,
    const std::function<deepdraw::geometry::ProjectionResult(const Point<3> &)>
                       &closest_point,
    const Tensor<1, 3> &f_ext,
    const Tensor<1, 3> &lambda_start  = Tensor<1, 3>(),
    const Linearisation linearisation = Linearisation::full)
  {
    Solution s;
    s.lambda = lambda_start;
    std::cout << "    r = " << r << ":";
    for (; s.iterations < 50; ++s.iterations)
    {
      const Point<3>              x = X_0 + s.du;
      const ContactPairKinematics kin(x,
                                      s.du,
                                      closest_point(x),
                                      Tensor<1, 3>(),
                                      Tensor<1, 3>(),
                                      linearisation);
      const ContactPairResult     res
        = evaluate_contact_pair(law, kin, s.lambda, r);
      s.state      = res.state;
      s.normal_gap = kin.normal_gap();
      s.normal     = kin.normal();

      const Tensor<1, 3> R_u = k * s.du - res.force - f_ext;
      const Tensor<1, 3> R_l = res.constraint_residual;
      // Residual in force units: r F_sup = λ − P.
      const double residual = std::max(R_u.norm(), r * R_l.norm());
      std::cout << " [" << to_string(res.state) << " " << residual << "]";
      if (residual <= 1e-12 * f_ext.norm())
      {
        s.converged = true;
        break;
      }

      Matrix6 J;
      Vector6 b;
      for (unsigned int i = 0; i < 3; ++i)
      {
        b[i]     = -R_u[i];
        b[i + 3] = -R_l[i];
        for (unsigned int j = 0; j < 3; ++j)
        {
          J[i][j]         = (i == j ? k : 0.) - res.dforce_ddisplacement[i][j];
          J[i][j + 3]     = -res.dforce_dmultiplier[i][j];
          J[i + 3][j]     = res.dconstraint_ddisplacement[i][j];
          J[i + 3][j + 3] = res.dconstraint_dmultiplier[i][j];
        }
      }
      const Vector6 dx = solve(J, b);
      for (unsigned int i = 0; i < 3; ++i)
      {
        s.du[i] += dx[i];
        s.lambda[i] += dx[i + 3];
      }
    }
    std::cout << "\n      " << s.iterations << " iterations" << std::endl;
    return s;
  }


  // The node pressed onto the top of a cylinder (radius 8, axis along y)
  // and pushed along its circumference: no closed form, so check the
  // contact conditions at the converged point, and that the answer is the
  // same for every r and for both linearisations.
  void
  cylinder(const double mu, const double F_T)
  {
    const double   k = 1000., R = 8., F_N = 500.;
    const Point<3> c(0., 0., -R);
    const Point<3> X_0(0.5, 0.3, 0.05);
    auto           tool
      = [&](const Point<3> &x) { return cylinder_closest_point(c, R, x); };
    const Tensor<1, 3>    f_ext({F_T, 0., -F_N});
    const AlartCurnierLaw law(mu);
    std::cout << "cylinder, mu = " << mu << ", F_T = " << F_T << std::endl;
    const std::string what = "cylinder, mu " + std::to_string(mu) + ", F_T "
                             + std::to_string(F_T) + ", ";
    Solution reference;
    bool     have_reference = false;
    for (const Linearisation lin :
         {Linearisation::full, Linearisation::frozen_normal})
    {
      const bool full = lin == Linearisation::full;
      std::cout << (full ? "   full linearisation" : "   frozen normal")
                << std::endl;
      for (const double r : {100., 1000., 1e4})
      {
        const Solution s
          = newton(law, r, k, X_0, tool, f_ext, Tensor<1, 3>(), lin);
        const std::string at = what + (full ? "full" : "frozen") + ", r "
                               + std::to_string(r) + ": ";
        check_true(at + "converged", s.converged);
        if (full)
          check_true(at + "in a handful of iterations", s.iterations <= 8);
        check_true(at + "in contact", s.state != ContactState::open);
        check_close(at + "g_N = 0", s.normal_gap, 0., 1e-12);
        const double       lambda_N = s.lambda * s.normal;
        const Tensor<1, 3> lambda_T = s.lambda - lambda_N * s.normal;
        check_true(at + "λ_N > 0", lambda_N > 0.);
        if (s.state == ContactState::slip)
          check_close(at + "slip: |λ_T| = μ λ_N",
                      lambda_T.norm(),
                      mu * lambda_N,
                      1e-10 * F_N);
        else
          check_true(at + "stick: |λ_T| <= μ λ_N",
                     lambda_T.norm() <= mu * lambda_N);
        if (!have_reference)
        {
          reference      = s;
          have_reference = true;
        }
        else
        {
          // The frozen normal converges only linearly: it stops within
          // 1e-12 |F| of the residual, not of the answer.
          const double tolerance = full ? 1e-12 : 1e-10;
          check_close(at + "same Δu",
                      (s.du - reference.du).norm(),
                      0.,
                      tolerance * reference.du.norm());
          check_close(at + "same λ",
                      (s.lambda - reference.lambda).norm(),
                      0.,
                      tolerance * F_N);
        }
      }
    }
    std::cout << "   Δu = " << reference.du << ", λ = " << reference.lambda
              << ", state " << to_string(reference.state) << std::endl;
  }
} // namespace

int
main()
{
  const double k = 1000., h0 = 0.05, F_N = 500.;
  const double rs[] = {10., 100., 1000., 1e4, 1e5};

  struct Load
  {
    const char  *name;
    double       mu, F_N, F_T;
    ContactState expected;
  };
  const Load loads[]
    = {{"stick (F_T = 50 < μN = 72.9)", 0.162, F_N, 50., ContactState::stick},
       {"slip (F_T = 100 > μN = 72.9)", 0.162, F_N, 100., ContactState::slip},
       {"slip, high friction (μ = 0.5, F_T = 300)",
        0.5,
        F_N,
        300.,
        ContactState::slip},
       {"frictionless (F_T = 100)", 0., F_N, 100., ContactState::slip},
       {"no contact (F_N = 30 < k h0)", 0.162, 30., 100., ContactState::open}};

  for (unsigned int frame = 0; frame < 2; ++frame)
  {
    const Tensor<1, 3> n
      = frame == 0 ? Tensor<1, 3>({0., 0., 1.}) : random_unit_vector();
    const Tensor<1, 3> t = random_tangent(n);
    const Point<3>     X_0(random_tangent(n) * 2. + h0 * n);
    std::cout << "plane normal " << n << ", load tangent " << t << std::endl;
    // The plane through the origin with normal n.
    const Tensor<1, 3> t1 = random_tangent(n), t2 = cross_product_3d(n, t1);
    auto               plane = [&](const Point<3> &x)
    {
      deepdraw::geometry::ProjectionResult cp;
      cp.foot      = x - (x * n) * n;
      cp.normal    = n;
      cp.tangent_u = t1;
      cp.tangent_v = t2;
      return cp;
    };

    for (const Load &load : loads)
    {
      std::cout << "  " << load.name << std::endl;
      const AlartCurnierLaw law(load.mu);
      const Tensor<1, 3>    f_ext = -load.F_N * n + load.F_T * t;
      const double          N     = load.F_N - k * h0;
      Tensor<1, 3>          du, lambda;
      if (N <= 0.)
        du = f_ext / k;
      else if (load.F_T <= load.mu * N)
      {
        du     = -h0 * n;
        lambda = N * n - load.F_T * t;
      }
      else
      {
        du     = -h0 * n + (load.F_T - load.mu * N) / k * t;
        lambda = N * n - load.mu * N * t;
      }

      // Cold start (λ = 0), and a warm start from a previous increment's
      // force whose friction part points elsewhere, so that the slip
      // direction has to turn during the iterations.
      const Tensor<1, 3> t_other = cross_product_3d(n, t);
      const Tensor<1, 3> lambda_warm
        = 400. * n + 0.5 * load.mu * 400. * (t_other - t);
      Solution first;
      for (unsigned int i = 0; i < 2 * std::size(rs); ++i)
      {
        const bool   warm = i >= std::size(rs);
        const double r    = rs[i % std::size(rs)];
        if (i % std::size(rs) == 0)
          std::cout << (warm ? "   warm start" : "   cold start") << std::endl;
        const Solution    s  = newton(law,
                                  r,
                                  k,
                                  X_0,
                                  plane,
                                  f_ext,
                                  warm ? lambda_warm : Tensor<1, 3>());
        const std::string at = std::string(load.name) + (warm ? ", warm" : "")
                               + ", r = " + std::to_string(r) + ": ";
        check_true(at + "converged", s.converged);
        check_true(at + "in a handful of iterations", s.iterations <= 8);
        check_true(at + std::string("final state ") + to_string(s.state),
                   s.state == load.expected);
        check_close(at + "Δu = analytic",
                    (s.du - du).norm(),
                    0.,
                    1e-12 * du.norm());
        check_close(at + "λ = analytic",
                    (s.lambda - lambda).norm(),
                    0.,
                    1e-12 * f_ext.norm());
        if (i == 0)
          first = s;
        else
        {
          check_close(at + "same Δu as r = 10",
                      (s.du - first.du).norm(),
                      0.,
                      1e-12 * du.norm());
          check_close(at + "same λ as r = 10",
                      (s.lambda - first.lambda).norm(),
                      0.,
                      1e-12 * f_ext.norm());
        }
      }
    }
  }
  cylinder(0.162, 50.);
  cylinder(0.162, 150.);
  cylinder(0., 150.);
  return deepdraw_test::summary();
}
