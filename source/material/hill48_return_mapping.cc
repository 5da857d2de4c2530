// The return mapping of ElastoPlasticity for Hill'48 (doc/theory_material.md
// §2-3): the closest-point projection solved in the eigenbasis of the Hill
// tensor as one scalar equation, and its exact tangent in closed form.
#include <algorithm>
#include <cmath>
#include <deepdraw/material/elasto_plasticity.h>
#include <limits>
#include <utility>

namespace deepdraw
{
  namespace material
  {
    using dealii::SymmetricTensor;

    namespace
    {
      // Raw storage of SymmetricTensor<2,3>: 0:11 1:22 2:33 3:12 4:13 5:23;
      // of SymmetricTensor<4,3>: entry (I,J) of the 6x6 array at 6*I + J,
      // holding the tensor component T_ijkl itself (no Kelvin weights).
      inline double &
      entry(SymmetricTensor<4, 3> &t,
            const unsigned int     I,
            const unsigned int     J)
      {
        return t.access_raw_entry(6 * I + J);
      }

      // Local Newton (doc/theory_material.md): |f| <= this * Y is converged,
      // well below the yield-check tolerance so that a converged state
      // re-evaluated with a zero increment is elastic.
      constexpr double       residual_tolerance = 1e-13;
      constexpr unsigned int max_iterations     = 60;
    } // namespace


    bool
    ElastoPlasticity::return_mapping_hill48(
      const MaterialPointState    &old_state,
      const SymmetricTensor<2, 3> &xi_trial,
      const double                 sigma_bar_trial,
      const double                 Y_n,
      const double                 dY_n,
      MaterialPointState          &new_state,
      SymmetricTensor<4, 3>       &consistent_tangent) const
    {
      const double mu                  = shear_modulus;
      const auto  &normal_eigenvalues  = hill48.spectrum().normal_eigenvalues;
      const auto  &normal_eigenvectors = hill48.spectrum().normal_eigenvectors;
      const auto  &shear_eigenvalues   = hill48.spectrum().shear_eigenvalues;
      const double smallest_eigenvalue = hill48.spectrum().smallest_eigenvalue;

      // Plastic corrector. With Delta eps^p = Delta lambda M:xi / sigma_bar,
      // Delta X = k Delta eps^p and C:M:xi = 2 mu M:xi (M deviatoric):
      //   (I + gamma beta M) xi = xi_trial,  gamma = Delta lambda / sigma_bar,
      //   beta = 2 mu + k.
      // In the eigenbasis of M each Kelvin coordinate w_a of xi_trial is
      // divided by (1 + gamma beta m_a); the hydrostatic one is unchanged.
      const double beta = 2. * mu + parameters.prager_modulus;
      double       w[5], m[5];
      for (unsigned int a = 0; a < 2; ++a)
      {
        w[a] = normal_eigenvectors[a][0] * xi_trial.access_raw_entry(0)
               + normal_eigenvectors[a][1] * xi_trial.access_raw_entry(1)
               + normal_eigenvectors[a][2] * xi_trial.access_raw_entry(2);
        m[a] = normal_eigenvalues[a];
      }
      for (unsigned int a = 0; a < 3; ++a)
      {
        w[2 + a] = std::sqrt(2.) * xi_trial.access_raw_entry(3 + a);
        m[2 + a] = shear_eigenvalues[a];
      }

      // Scalar equation for gamma (doc/theory_material.md), written as
      //   r(gamma) = 1/sigma_bar(gamma) - 1/Y(epbar_n + gamma sigma_bar) = 0,
      // with sigma_bar^2 = sum m_a w_a^2 / (1 + gamma beta m_a)^2. For von
      // Mises 1/sigma_bar is linear in gamma, so this form is nearly linear
      // and Newton takes few steps even for large increments. r(0) < 0, r
      // increases strictly, and since sigma_bar <= sigma_bar_trial /
      // (1 + gamma beta m_min) and Y >= Y_n, r(upper) >= 0: safeguarded
      // Newton (bisection when Newton leaves the bracket).
      // d sigma_bar / d gamma = -beta Q / sigma_bar,
      // Q = sum m_a^2 w_a^2 / (1 + gamma beta m_a)^3.
      const double epbar_n   = old_state.equivalent_plastic_strain;
      double       sigma_bar = sigma_bar_trial, Q = 0., Y = Y_n, dY = dY_n;
      // Returns r and dr/dgamma; leaves sigma_bar, Q, Y, dY at gamma.
      auto evaluate = [&](const double gamma)
      {
        double s2 = 0.;
        Q         = 0.;
        for (unsigned int a = 0; a < 5; ++a)
        {
          const double r  = 1. / (1. + gamma * beta * m[a]);
          const double mw = m[a] * w[a] * r;
          s2 += mw * w[a] * r;
          Q += mw * mw * r;
        }
        sigma_bar = std::sqrt(s2);
        hardening.evaluate(epbar_n + gamma * sigma_bar, Y, dY);
        const double dsigma_bar = -beta * Q / sigma_bar;
        return std::make_pair(1. / sigma_bar - 1. / Y,
                              -dsigma_bar / (sigma_bar * sigma_bar)
                                + dY * (sigma_bar + gamma * dsigma_bar)
                                    / (Y * Y));
      };

      double lower = 0.;
      double upper
        = (sigma_bar_trial / Y_n - 1.) / (beta * smallest_eigenvalue);
      double gamma     = 0.;
      auto   r_dr      = evaluate(gamma);
      bool   converged = false;
      for (unsigned int iteration = 0; iteration < max_iterations; ++iteration)
      {
        double next = gamma - r_dr.first / r_dr.second;
        if (!(next > lower && next < upper))
          next = 0.5 * (lower + upper);
        const double step = next - gamma;
        gamma             = next;
        r_dr              = evaluate(gamma);
        if (!std::isfinite(r_dr.first))
          return false;
        (r_dr.first < 0. ? lower : upper) = gamma;
        // Converged: |sigma_bar - Y| <= tolerance Y, or the step reached
        // round-off.
        if (std::abs(sigma_bar - Y) <= residual_tolerance * Y
            || std::abs(step)
                 <= 4. * std::numeric_limits<double>::epsilon() * gamma)
        {
          converged = true;
          break;
        }
      }
      if (!converged)
        return false;

      // New state: xi = sum_a w_a / (1 + gamma beta m_a) q_a + hydrostatic,
      // Delta eps^p = gamma M:xi, X = X_n + k Delta eps^p,
      // epbar = epbar_n + gamma sigma_bar (plastic-work equivalence).
      const double k = parameters.prager_modulus;
      double       r[5], w_new[5];
      for (unsigned int a = 0; a < 5; ++a)
      {
        r[a]     = 1. / (1. + gamma * beta * m[a]);
        w_new[a] = w[a] * r[a];
      }
      const double pressure = trace(xi_trial) / 3.;
      // M:xi and b = (I + gamma beta M)^{-1} M:xi as tensors (raw order).
      double xi[6], Mxi[6], b[6];
      for (unsigned int i = 0; i < 3; ++i)
      {
        xi[i]  = pressure;
        Mxi[i] = b[i] = 0.;
        for (unsigned int a = 0; a < 2; ++a)
        {
          const double q = normal_eigenvectors[a][i];
          xi[i] += w_new[a] * q;
          Mxi[i] += m[a] * w_new[a] * q;
          b[i] += m[a] * w_new[a] * r[a] * q;
        }
      }
      for (unsigned int a = 0; a < 3; ++a)
      {
        // Kelvin coordinate w = sqrt2 xi_12, so the tensor entry is w/sqrt2.
        xi[3 + a]  = w_new[2 + a] / std::sqrt(2.);
        Mxi[3 + a] = m[2 + a] * xi[3 + a];
        b[3 + a]   = Mxi[3 + a] * r[2 + a];
      }
      for (unsigned int I = 0; I < 6; ++I)
      {
        const double X
          = old_state.back_stress.access_raw_entry(I) + k * gamma * Mxi[I];
        new_state.back_stress.access_raw_entry(I) = X;
        new_state.stress.access_raw_entry(I)      = X + xi[I];
      }
      new_state.equivalent_plastic_strain = epbar_n + gamma * sigma_bar;

      // Exact algorithmic tangent (doc/theory_material.md), in Kelvin form
      //   T = K 1(x)1 + 2 mu sum_a rho_a q_a (x) q_a - kappa b (x) b,
      //   rho_a = (1 + gamma k m_a) / (1 + gamma beta m_a),
      //   kappa = 4 mu^2 (1 - Y' gamma) / D,
      //   D = Y' sigma_bar^2 + (1 - Y' gamma) beta Q = -sigma_bar df/dgamma,
      // from differentiating the update and the consistency condition
      // (dgamma depends on the strain increment). Major-symmetric.
      const double kappa
        = 4. * mu * mu * (1. - dY * gamma)
          / (dY * sigma_bar * sigma_bar + (1. - dY * gamma) * beta * Q);
      double rho[5];
      for (unsigned int a = 0; a < 5; ++a)
        rho[a] = (1. + gamma * k * m[a]) * r[a];
      for (unsigned int I = 0; I < 3; ++I)
        for (unsigned int J = 0; J < 3; ++J)
          entry(consistent_tangent, I, J)
            = bulk_modulus
              + 2. * mu
                  * (rho[0] * normal_eigenvectors[0][I]
                       * normal_eigenvectors[0][J]
                     + rho[1] * normal_eigenvectors[1][I]
                         * normal_eigenvectors[1][J])
              - kappa * b[I] * b[J];
      // Shear entries of the tensor: T_1212 = (Kelvin entry) / 2, T_11 12 =
      // (Kelvin entry) / sqrt2; with b stored as tensor entries the b (x) b
      // term needs no weights.
      for (unsigned int I = 0; I < 6; ++I)
        for (unsigned int J = 3; J < 6; ++J)
        {
          double value = -kappa * b[I] * b[J];
          if (I == J)
            value += mu * rho[J - 1];
          entry(consistent_tangent, I, J) = value;
          entry(consistent_tangent, J, I) = value;
        }
      return true;
    }
  } // namespace material
} // namespace deepdraw
