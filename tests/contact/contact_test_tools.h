// Helpers shared by the contact unit tests: random directions, finite
// differences compared block by block, and exact parametric tool surfaces
// with their own closest-point projection (independent of the library).
#ifndef deepdraw_tests_contact_contact_test_tools_h
#define deepdraw_tests_contact_contact_test_tools_h

#include "test_utilities.h"

#include <cmath>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deepdraw/geometry/projection_result.h>
#include <functional>
#include <random>
#include <string>

namespace contact_test
{
  using dealii::Point;
  using dealii::Tensor;

  inline std::mt19937 &
  generator()
  {
    static std::mt19937 g(20240611);
    return g;
  }

  inline double
  random_in(const double a, const double b)
  {
    return std::uniform_real_distribution<double>(a, b)(generator());
  }

  inline Tensor<1, 3>
  random_vector(const double scale = 1.)
  {
    Tensor<1, 3> v;
    for (unsigned int i = 0; i < 3; ++i)
      v[i] = random_in(-scale, scale);
    return v;
  }

  inline Tensor<1, 3>
  random_unit_vector()
  {
    Tensor<1, 3> v;
    do
      v = random_vector();
    while (v.norm() < 0.2 || v.norm() > 1.);
    return v / v.norm();
  }

  // A unit vector orthogonal to n.
  inline Tensor<1, 3>
  random_tangent(const Tensor<1, 3> &n)
  {
    Tensor<1, 3> t;
    do
    {
      t = random_vector();
      t -= (t * n) * n;
    } while (t.norm() < 0.2);
    return t / t.norm();
  }

  inline Tensor<2, 3>
  identity()
  {
    Tensor<2, 3> I;
    for (unsigned int i = 0; i < 3; ++i)
      I[i][i] = 1.;
    return I;
  }

  // Central difference of f: R³ → R³ at x0, column j = ∂f/∂x_j.
  inline Tensor<2, 3>
  fd_jacobian(const std::function<Tensor<1, 3>(const Tensor<1, 3> &)> &f,
              const Tensor<1, 3>                                      &x0,
              const double                                             h)
  {
    Tensor<2, 3> J;
    for (unsigned int j = 0; j < 3; ++j)
    {
      Tensor<1, 3> xp = x0, xm = x0;
      xp[j] += h;
      xm[j] -= h;
      const Tensor<1, 3> df = (f(xp) - f(xm)) / (2. * h);
      for (unsigned int i = 0; i < 3; ++i)
        J[i][j] = df[i];
    }
    return J;
  }

  inline Tensor<1, 3>
  fd_derivative(const std::function<Tensor<1, 3>(const double)> &f,
                const double                                     x0,
                const double                                     h)
  {
    return (f(x0 + h) - f(x0 - h)) / (2. * h);
  }

  // max |analytic − fd| relative to max |analytic| (absolute if that is 0).
  template <int rank>
  inline void
  check_block(const std::string     &what,
              const Tensor<rank, 3> &analytic,
              const Tensor<rank, 3> &fd,
              const double           tolerance = 1e-7)
  {
    const double error = (analytic - fd).norm();
    const double scale = analytic.norm();
    if (scale > 0.)
      deepdraw_test::check_close(what + " rel. error",
                                 error / scale,
                                 0.,
                                 tolerance);
    else
      deepdraw_test::check_close(what + " (zero) abs. error",
                                 error,
                                 0.,
                                 tolerance);
  }

  // Exact parametric surface x̄(u, v) with derivatives up to second order;
  // n = orientation (x̄_u × x̄_v)/|x̄_u × x̄_v|.
  struct Surface
  {
    virtual ~Surface() = default;
    virtual void
           evaluate(const double u,
                    const double v,
                    Tensor<1, 3> (&S)[6]) const = 0; // S, Su, Sv, Suu, Suv, Svv
    double orientation                          = 1.;
  };

  // Ring torus about the z axis (radii R, rho); outward normal for
  // orientation +1.
  struct Torus : Surface
  {
    Torus(const Point<3> &c, const double R, const double rho, const double o)
        : center(c)
        , R(R)
        , rho(rho)
    {
      orientation = o;
    }
    void
    evaluate(const double u,
             const double v,
             Tensor<1, 3> (&S)[6]) const override
    {
      const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v),
                   sv = std::sin(v), w = R + rho * cv;
      S[0] = Tensor<1, 3>({w * cu, w * su, rho * sv}) + center;
      S[1] = Tensor<1, 3>({-w * su, w * cu, 0.});
      S[2] = Tensor<1, 3>({-rho * sv * cu, -rho * sv * su, rho * cv});
      S[3] = Tensor<1, 3>({-w * cu, -w * su, 0.});
      S[4] = Tensor<1, 3>({rho * sv * su, -rho * sv * cu, 0.});
      S[5] = Tensor<1, 3>({-rho * cv * cu, -rho * cv * su, -rho * sv});
    }
    Tensor<1, 3> center;
    double       R, rho;
  };

  // Sphere (centre c, radius R); orientation −1: normal towards the centre
  // (a concave tool, the node inside).
  struct Sphere : Surface
  {
    Sphere(const Point<3> &c, const double R, const double o)
        : center(c)
        , R(R)
    {
      orientation = o;
    }
    void
    evaluate(const double u,
             const double v,
             Tensor<1, 3> (&S)[6]) const override
    {
      const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v),
                   sv = std::sin(v);
      S[0]            = R * Tensor<1, 3>({cv * cu, cv * su, sv}) + center;
      S[1]            = R * Tensor<1, 3>({-cv * su, cv * cu, 0.});
      S[2]            = R * Tensor<1, 3>({-sv * cu, -sv * su, cv});
      S[3]            = R * Tensor<1, 3>({-cv * cu, -cv * su, 0.});
      S[4]            = R * Tensor<1, 3>({sv * su, -sv * cu, 0.});
      S[5]            = R * Tensor<1, 3>({-cv * cu, -cv * su, -sv});
    }
    Tensor<1, 3> center;
    double       R;
  };

  // Paraboloid over skewed (non-orthogonal) parameters:
  // x̄ = u e1 + v e2 + ½(α u² + 2β uv + γ v²) e3, e1, e2, e3 not orthonormal.
  struct SkewParaboloid : Surface
  {
    SkewParaboloid()
    {
      e1    = Tensor<1, 3>({1., 0.1, 0.});
      e2    = Tensor<1, 3>({0.4, 1., -0.1});
      e3    = Tensor<1, 3>({0., 0.2, 1.});
      alpha = 0.3;
      beta  = -0.12;
      gamma = -0.2;
    }
    void
    evaluate(const double u,
             const double v,
             Tensor<1, 3> (&S)[6]) const override
    {
      S[0] = u * e1 + v * e2
             + 0.5 * (alpha * u * u + 2 * beta * u * v + gamma * v * v) * e3;
      S[1] = e1 + (alpha * u + beta * v) * e3;
      S[2] = e2 + (beta * u + gamma * v) * e3;
      S[3] = alpha * e3;
      S[4] = beta * e3;
      S[5] = gamma * e3;
    }
    Tensor<1, 3> e1, e2, e3;
    double       alpha, beta, gamma;
  };

  // Closest point of x on the surface translated by `shift`, by Newton on
  // (u, v) from (u, v) (updated in place), to machine precision.
  inline deepdraw::geometry::ProjectionResult
  project(const Surface      &surface,
          const Point<3>     &x,
          const Tensor<1, 3> &shift,
          double             &u,
          double             &v)
  {
    const Tensor<1, 3> y = x - shift;
    Tensor<1, 3>       S[6];
    for (unsigned int it = 0; it < 100; ++it)
    {
      surface.evaluate(u, v, S);
      const Tensor<1, 3> r  = y - S[0];
      const double       f0 = r * S[1], f1 = r * S[2];
      const double       H00 = S[1] * S[1] - r * S[3];
      const double       H01 = S[1] * S[2] - r * S[4];
      const double       H11 = S[2] * S[2] - r * S[5];
      const double       det = H00 * H11 - H01 * H01;
      const double       du  = (H11 * f0 - H01 * f1) / det;
      const double       dv  = (-H01 * f0 + H00 * f1) / det;
      u += du;
      v += dv;
      if (std::abs(du) + std::abs(dv) < 1e-15)
        break;
    }
    surface.evaluate(u, v, S);
    deepdraw::geometry::ProjectionResult cp;
    cp.foot        = Point<3>(S[0] + shift);
    Tensor<1, 3> n = cross_product_3d(S[1], S[2]);
    cp.normal      = surface.orientation * n / n.norm();
    cp.tangent_u   = S[1];
    cp.tangent_v   = S[2];
    cp.x_uu        = S[3];
    cp.x_uv        = S[4];
    cp.x_vv        = S[5];
    return cp;
  }
} // namespace contact_test

#endif
