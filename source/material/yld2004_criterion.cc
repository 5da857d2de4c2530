#include <algorithm>
#include <cmath>
#include <deepdraw/material/yld2004_criterion.h>
#include <limits>
#include <sstream>
#include <utility>

namespace deepdraw
{
  namespace material
  {
    using kelvin::Matrix;
    using kelvin::Vector;

    namespace
    {
      // Off-diagonal pairs of a symmetric 3 x 3 matrix: the order of the
      // shear entries of the Kelvin storage (12, 13, 23) and of the spectral
      // shear modes (doc/theory_material.md §3.2).
      constexpr unsigned int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};

      struct Spectral
      {
        double values[3];
        double vectors[3][3]; // vectors[i]: unit eigenvector of values[i]
      };

      // Cyclic Jacobi: accurate eigenvalues also when they (nearly)
      // coincide, and an orthonormal basis in every case. a is destroyed.
      Spectral
      jacobi(double a[3][3])
      {
        double v[3][3] = {{1., 0., 0.}, {0., 1., 0.}, {0., 0., 1.}};
        for (unsigned int sweep = 0; sweep < 50; ++sweep)
        {
          bool rotated = false;
          for (const auto &[p, q] : pairs)
          {
            const double apq = a[p][q];
            // Below this the rotation would not change the diagonal.
            if (std::abs(apq)
                <= 1e-18 * (std::abs(a[p][p]) + std::abs(a[q][q])))
            {
              a[p][q] = a[q][p] = 0.;
              continue;
            }
            rotated            = true;
            const double theta = (a[q][q] - a[p][p]) / (2. * apq);
            const double t
              = (theta >= 0. ? 1. : -1.)
                / (std::abs(theta) + std::sqrt(theta * theta + 1.));
            const double       c = 1. / std::sqrt(t * t + 1.), s = t * c;
            const unsigned int r   = 3 - p - q;
            const double       arp = a[r][p], arq = a[r][q];
            a[r][p] = a[p][r] = c * arp - s * arq;
            a[r][q] = a[q][r] = s * arp + c * arq;
            a[p][p] -= t * apq;
            a[q][q] += t * apq;
            a[p][q] = a[q][p] = 0.;
            for (unsigned int k = 0; k < 3; ++k)
            {
              const double vkp = v[k][p], vkq = v[k][q];
              v[k][p] = c * vkp - s * vkq;
              v[k][q] = s * vkp + c * vkq;
            }
          }
          if (!rotated)
            break;
        }
        Spectral result;
        for (unsigned int i = 0; i < 3; ++i)
        {
          result.values[i] = a[i][i];
          for (unsigned int k = 0; k < 3; ++k)
            result.vectors[i][k] = v[k][i];
        }
        return result;
      }

      // Spectral decomposition of the symmetric tensor with Kelvin
      // coordinates s.
      Spectral
      spectral_decomposition(const Vector &s)
      {
        const double r       = 1. / std::sqrt(2.);
        double       a[3][3] = {{s[0], r * s[3], r * s[4]},
                                {r * s[3], s[1], r * s[5]},
                                {r * s[4], r * s[5], s[2]}};
        return jacobi(a);
      }

      // Kelvin matrix of xi -> C s (s = dev xi), C as in Barlat et al.
      // (2005) with the coefficients in the paper's order c12 c13 c21 c23
      // c31 c32 c44 c55 c66 (4 = yz, 5 = zx, 6 = xy).
      Matrix
      transformation_matrix(const std::array<double, 9> &c)
      {
        const double C[3][3]
          = {{0., -c[0], -c[1]}, {-c[2], 0., -c[3]}, {-c[4], -c[5], 0.}};
        Matrix L{};
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            for (unsigned int k = 0; k < 3; ++k)
              L[i][j] += C[i][k] * ((k == j ? 1. : 0.) - 1. / 3.);
        // Kelvin shear entries (raw order 12, 13, 23): S'_12 = c66 s_12 etc.
        L[3][3] = c[8];
        L[4][4] = c[7];
        L[5][5] = c[6];
        return L;
      }

      // Rows 0-2: Kelvin coordinates of e_i (x) e_i; rows 3-5: of the unit
      // shears (e_i (x) e_k + e_k (x) e_i) / sqrt2 of `pairs`. Orthonormal.
      Matrix
      spectral_basis(const Spectral &spectral)
      {
        const double r = std::sqrt(2.);
        Matrix       P;
        for (unsigned int i = 0; i < 3; ++i)
        {
          const double *v = spectral.vectors[i];
          for (unsigned int k = 0; k < 3; ++k)
            P[i][k] = v[k] * v[k];
          for (unsigned int k = 0; k < 3; ++k)
            P[i][3 + k] = r * v[pairs[k][0]] * v[pairs[k][1]];
        }
        for (unsigned int p = 0; p < 3; ++p)
        {
          const double *v = spectral.vectors[pairs[p][0]];
          const double *w = spectral.vectors[pairs[p][1]];
          for (unsigned int k = 0; k < 3; ++k)
            P[3 + p][k] = r * v[k] * w[k];
          for (unsigned int k = 0; k < 3; ++k)
          {
            const unsigned int m = pairs[k][0], n = pairs[k][1];
            P[3 + p][3 + k] = v[m] * w[n] + v[n] * w[m];
          }
        }
        return P;
      }

      // [psi'(x) - psi'(y)] / (x - y) for psi'(x) = |x|^(a-2) x, given
      // qx = |x|^(a-2), qy = |y|^(a-2): the spin coefficient of the Hessian
      // (doc/theory_material.md §3.2). Its limit (a-1) |x|^(a-2) for y = x,
      // and without cancellation for y close to x: with v the larger
      // magnitude and t = (|u| - |v|) / |v|, the quotient is
      // |v|^(a-2) [(1 + t)^(a-1) - 1] / t = |v|^(a-2) expm1((a-1)
      // log1p(t)) / t.
      double
      divided_difference(const double x,
                         const double y,
                         const double qx,
                         const double qy,
                         const double a)
      {
        if (x == y)
          return (a - 1.) * qx;
        const bool same_sign = (x > 0. && y > 0.) || (x < 0. && y < 0.);
        double     u = std::abs(x), v = std::abs(y), qv = qy;
        if (u > v)
        {
          std::swap(u, v);
          qv = qx;
        }
        const double t = (u - v) / v;
        // Opposite signs, or magnitudes far apart: the plain quotient has
        // no cancellation.
        if (!same_sign || t < -0.5)
          return (qx * x - qy * y) / (x - y);
        return qv * std::expm1((a - 1.) * std::log1p(t)) / t;
      }
      // The nine differences S'_i - S''_j scaled by the largest, m, so that
      // |x| <= 1 and no power overflows or underflows (§1.2): x, q = |x|^(a-2),
      // phi_hat = sum q x^2 (sigma_bar = m phi_hat^(1/a) / phi_0^(1/a)) and
      // g'_i = sum_j q x, g''_j = -sum_i q x (the gradient in the principal
      // values up to a factor). m = 0 for S' = S'' = c I.
      struct Differences
      {
        double m = 0., phi = 0.;
        double x[3][3], q[3][3];
        double g[2][3] = {};
      };

      Differences
      differences(const Spectral spectral[2], const double a)
      {
        const double *l = spectral[0].values, *mu = spectral[1].values;
        Differences   d;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            d.m = std::max(d.m, std::abs(l[i] - mu[j]));
        if (d.m == 0.)
          return d;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
          {
            const double x = (l[i] - mu[j]) / d.m;
            d.x[i][j]      = x;
            d.q[i][j]      = std::pow(std::abs(x), a - 2.);
            d.phi += d.q[i][j] * x * x;
            d.g[0][i] += d.q[i][j] * x;
            d.g[1][j] -= d.q[i][j] * x;
          }
        return d;
      }

      // H = d^2 sigma / d xi^2 from the second derivatives in the spectral
      // coordinates B[t] xi of S' and S'' (§3.2): diagonal within each of
      // S', S'' (principal parts (a-1) c sum q, spin parts c sum D),
      // coupled between the principal parts of S' and S'' (-(a-1) c q), and
      // -(a-1) / sigma n (x) n; c = kappa / m.
      void
      assemble_hessian(const Differences &d,
                       const double       a,
                       const double       c,
                       const Matrix       B[2],
                       const double       sigma,
                       const Vector      &n,
                       Matrix            &H)
      {
        double diagonal[2][6] = {};
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
          {
            diagonal[0][i] += (a - 1.) * c * d.q[i][j];
            diagonal[1][j] += (a - 1.) * c * d.q[i][j];
          }
        for (unsigned int p = 0; p < 3; ++p)
        {
          const unsigned int i = pairs[p][0], k = pairs[p][1];
          for (unsigned int j = 0; j < 3; ++j)
          {
            diagonal[0][3 + p] += c
                                  * divided_difference(d.x[i][j],
                                                       d.x[k][j],
                                                       d.q[i][j],
                                                       d.q[k][j],
                                                       a);
            diagonal[1][3 + p] += c
                                  * divided_difference(d.x[j][i],
                                                       d.x[j][k],
                                                       d.q[j][i],
                                                       d.q[j][k],
                                                       a);
          }
        }
        for (unsigned int I = 0; I < 6; ++I)
          for (unsigned int J = 0; J < 6; ++J)
          {
            double s = -(a - 1.) / sigma * n[I] * n[J];
            for (unsigned int t = 0; t < 2; ++t)
              for (unsigned int alpha = 0; alpha < 6; ++alpha)
                s += diagonal[t][alpha] * B[t][alpha][I] * B[t][alpha][J];
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                s -= (a - 1.) * c * d.q[i][j]
                     * (B[0][i][I] * B[1][j][J] + B[1][j][I] * B[0][i][J]);
            H[I][J] = s;
          }
      }
    } // namespace


    Yld2004Criterion::Yld2004Criterion(const MaterialParameters &parameters)
        : exponent(parameters.yld2004_exponent)
        , transformation{transformation_matrix(parameters.yld2004_c1),
                         transformation_matrix(parameters.yld2004_c2)}
        , normalisation(1.)
    {
      // phi_0^(1/a) = raw sigma_bar of unit tension along the rolling
      // direction (doc/theory_material.md §1.2).
      const Vector e1 = {{1., 0., 0., 0., 0., 0.}};
      normalisation   = evaluate_raw(e1, nullptr, nullptr);
    }


    double
    Yld2004Criterion::evaluate_raw(const Vector &xi,
                                   Vector       *gradient,
                                   Matrix       *hessian) const
    {
      // A non-finite stress gives a non-finite sigma_bar (the caller then
      // reports failure), not the 0 that std::max would make of NaN.
      double sum = 0.;
      for (const double x : xi)
        sum += x;
      if (!std::isfinite(sum))
        return std::numeric_limits<double>::quiet_NaN();
      Spectral spectral[2];
      for (unsigned int t = 0; t < 2; ++t)
      {
        Vector S{};
        for (unsigned int I = 0; I < 6; ++I)
          for (unsigned int J = 0; J < 6; ++J)
            S[I] += transformation[t][I][J] * xi[J];
        spectral[t] = spectral_decomposition(S);
      }
      if (gradient != nullptr)
        gradient->fill(0.);
      if (hessian != nullptr)
        for (Vector &row : *hessian)
          row.fill(0.);
      const Differences d = differences(spectral, exponent);
      if (d.m == 0.)
        return 0.;
      const double sigma = d.m * std::pow(d.phi, 1. / exponent);
      if (gradient == nullptr)
        return sigma;

      // d sigma / d S'_i = kappa g'_i, d sigma / d S''_j = kappa g''_j;
      // B[t] = P[t] L[t] maps xi to the spectral coordinates of S', S''.
      const double kappa = sigma / (d.m * d.phi);
      Matrix       B[2];
      for (unsigned int t = 0; t < 2; ++t)
      {
        const Matrix P = spectral_basis(spectral[t]);
        for (unsigned int alpha = 0; alpha < 6; ++alpha)
          for (unsigned int J = 0; J < 6; ++J)
          {
            double s = 0.;
            for (unsigned int I = 0; I < 6; ++I)
              s += P[alpha][I] * transformation[t][I][J];
            B[t][alpha][J] = s;
          }
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int J = 0; J < 6; ++J)
            (*gradient)[J] += kappa * d.g[t][i] * B[t][i][J];
      }
      if (hessian != nullptr)
        assemble_hessian(d,
                         exponent,
                         kappa / d.m,
                         B,
                         sigma,
                         *gradient,
                         *hessian);
      return sigma;
    }


    double
    Yld2004Criterion::evaluate(const Vector &xi,
                               Vector       &gradient,
                               Matrix       *hessian) const
    {
      const double sigma = evaluate_raw(xi, &gradient, hessian);
      // sigma_bar is homogeneous of degree 1: all three scale alike.
      for (double &g : gradient)
        g /= normalisation;
      if (hessian != nullptr)
        for (Vector &row : *hessian)
          for (double &h : row)
            h /= normalisation;
      return sigma / normalisation;
    }


    double
    Yld2004Criterion::equivalent_stress(
      const dealii::SymmetricTensor<2, 3> &xi) const
    {
      return evaluate_raw(kelvin::from_tensor(xi), nullptr, nullptr)
             / normalisation;
    }


    double
    Yld2004Criterion::raw_rolling_direction_factor() const
    {
      return std::pow(normalisation, exponent) / 4.;
    }


    std::string
    Yld2004Criterion::degenerate_mode(const std::array<double, 9> &c1,
                                      const std::array<double, 9> &c2)
    {
      // A shear component that neither transformation sees.
      const char *const shear[3]
        = {"the shear stress 23 (yz; c'44 = c''44 = 0)",
           "the shear stress 31 (zx; c'55 = c''55 = 0)",
           "the shear stress 12 (xy; c'66 = c''66 = 0)"};
      for (unsigned int k = 0; k < 3; ++k)
        if (std::max(std::abs(c1[6 + k]), std::abs(c2[6 + k])) <= 1e-6)
          return shear[k];

      // phi = 0 for a normal deviator s iff C' s = C'' s = c (1, 1, 1): a
      // null vector (alpha_1, alpha_2, c) of the 6 x 3 matrix A of
      // s = alpha_1 d1 + alpha_2 d2 -> (C' s - c 1, C'' s - c 1).
      const double d[2][3]
        = {{1. / std::sqrt(2.), -1. / std::sqrt(2.), 0.},
           {1. / std::sqrt(6.), 1. / std::sqrt(6.), -2. / std::sqrt(6.)}};
      const Matrix L[2]
        = {transformation_matrix(c1), transformation_matrix(c2)};
      double A[6][3];
      for (unsigned int t = 0; t < 2; ++t)
        for (unsigned int i = 0; i < 3; ++i)
        {
          for (unsigned int b = 0; b < 2; ++b)
          {
            A[3 * t + i][b] = 0.;
            for (unsigned int j = 0; j < 3; ++j)
              A[3 * t + i][b] += L[t][i][j] * d[b][j];
          }
          A[3 * t + i][2] = -1. / std::sqrt(6.);
        }
      double gram[3][3] = {};
      for (unsigned int b = 0; b < 3; ++b)
        for (unsigned int e = 0; e < 3; ++e)
          for (unsigned int r = 0; r < 6; ++r)
            gram[b][e] += A[r][b] * A[r][e];
      const Spectral     spectral = jacobi(gram);
      const double      *values   = spectral.values;
      const unsigned int smallest
        = std::min_element(values, values + 3) - values;
      // Singular values 1e-6 apart: an unbounded, or absurdly elongated,
      // yield surface.
      if (values[smallest] > 1e-12 * *std::max_element(values, values + 3))
        return "";
      const double *null = spectral.vectors[smallest];
      double        s[3];
      double        norm = 0.;
      for (unsigned int j = 0; j < 3; ++j)
      {
        s[j] = null[0] * d[0][j] + null[1] * d[1][j];
        norm = std::max(norm, std::abs(s[j]));
      }
      std::ostringstream text;
      text.precision(3);
      for (double &component : s)
        component = std::abs(component) < 1e-9 * norm ? 0. : component / norm;
      text << "the normal deviator (s11, s22, s33) = (" << s[0] << ", " << s[1]
           << ", " << s[2] << ")";
      return text.str();
    }
  } // namespace material
} // namespace deepdraw
