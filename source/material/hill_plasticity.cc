#include <algorithm>
#include <cmath>
#include <deepdraw/material/hill_plasticity.h>
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
      constexpr double       yield_tolerance    = 1e-12;
      constexpr unsigned int max_iterations     = 60;
    } // namespace


    HillPlasticity::HillPlasticity(const MaterialParameters &parameters)
        : parameters(parameters)
    {
      parameters.validate();

      const double E  = parameters.youngs_modulus;
      const double nu = parameters.poissons_ratio;
      shear_modulus   = E / (2. * (1. + nu));
      lame_lambda     = E * nu / ((1. + nu) * (1. - 2. * nu));
      bulk_modulus    = E / (3. * (1. - 2. * nu));

      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          elasticity[i][i][j][j]
            = lame_lambda + (i == j ? 2. * shear_modulus : 0.);
      elasticity[0][1][0][1] = elasticity[0][2][0][2] = elasticity[1][2][1][2]
        = shear_modulus;

      // Hill tensor: normal block P (sigma_bar^2 = xi_n . P xi_n + ...), and
      // M_1212 = N/2 etc. because xi : M : xi counts xi_12 M_1212 xi_12 four
      // times (12 and 21 in both pairs): 4 (N/2) xi_12^2 = 2 N xi_12^2.
      const double F = parameters.hill_F, G = parameters.hill_G,
                   H = parameters.hill_H;
      const double P[3][3]
        = {{G + H, -H, -G}, {-H, F + H, -F}, {-G, -F, F + G}};
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          hill[i][i][j][j] = P[i][j];
      hill[0][1][0][1] = 0.5 * parameters.hill_N;
      hill[0][2][0][2] = 0.5 * parameters.hill_M;
      hill[1][2][1][2] = 0.5 * parameters.hill_L;

      // Spectral form of M in the Kelvin basis. P (1,1,1) = 0 exactly, so the
      // hydrostatic mode has eigenvalue 0; the other two lie in the deviatoric
      // plane, spanned by d1 = (1,-1,0)/sqrt2, d2 = (1,1,-2)/sqrt6: diagonalise
      // the 2x2 projection of P there in closed form.
      const double d[2][3]
        = {{1. / std::sqrt(2.), -1. / std::sqrt(2.), 0.},
           {1. / std::sqrt(6.), 1. / std::sqrt(6.), -2. / std::sqrt(6.)}};
      double p[2][2];
      for (unsigned int a = 0; a < 2; ++a)
        for (unsigned int b = 0; b < 2; ++b)
        {
          p[a][b] = 0.;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              p[a][b] += d[a][i] * P[i][j] * d[b][j];
        }
      const double mean   = 0.5 * (p[0][0] + p[1][1]);
      const double radius = std::hypot(0.5 * (p[0][0] - p[1][1]), p[0][1]);
      const double theta  = 0.5 * std::atan2(2. * p[0][1], p[0][0] - p[1][1]);
      const double c = std::cos(theta), s = std::sin(theta);
      normal_eigenvalues[0] = mean + radius;
      normal_eigenvalues[1] = mean - radius;
      for (unsigned int i = 0; i < 3; ++i)
      {
        normal_eigenvectors[0][i] = c * d[0][i] + s * d[1][i];
        normal_eigenvectors[1][i] = -s * d[0][i] + c * d[1][i];
      }
      // Raw order of the shear entries: 12, 13, 23.
      shear_eigenvalues[0] = parameters.hill_N;
      shear_eigenvalues[1] = parameters.hill_M;
      shear_eigenvalues[2] = parameters.hill_L;
      smallest_eigenvalue  = std::min({normal_eigenvalues[1],
                                       shear_eigenvalues[0],
                                       shear_eigenvalues[1],
                                       shear_eigenvalues[2]});
    }


    double
    HillPlasticity::equivalent_stress(const SymmetricTensor<2, 3> &xi) const
    {
      const double d23 = xi[1][1] - xi[2][2], d31 = xi[2][2] - xi[0][0],
                   d12 = xi[0][0] - xi[1][1];
      const double q   = parameters.hill_F * d23 * d23
                       + parameters.hill_G * d31 * d31
                       + parameters.hill_H * d12 * d12
                       + 2.
                           * (parameters.hill_L * xi[1][2] * xi[1][2]
                              + parameters.hill_M * xi[0][2] * xi[0][2]
                              + parameters.hill_N * xi[0][1] * xi[0][1]);
      return std::sqrt(std::max(q, 0.));
    }


    void
    HillPlasticity::swift(const double epbar, double &Y, double &dY) const
    {
      const double strain = parameters.swift_prestrain + epbar;
      Y                   = parameters.swift_coefficient
          * std::pow(strain, parameters.swift_exponent);
      dY = parameters.swift_exponent * Y / strain;
    }


    double
    HillPlasticity::yield_stress(const double equivalent_plastic_strain) const
    {
      double Y, dY;
      swift(equivalent_plastic_strain, Y, dY);
      return Y;
    }


    double
    HillPlasticity::hardening_modulus(
      const double equivalent_plastic_strain) const
    {
      double Y, dY;
      swift(equivalent_plastic_strain, Y, dY);
      return dY;
    }


    const SymmetricTensor<4, 3> &
    HillPlasticity::elasticity_tensor() const
    {
      return elasticity;
    }


    const SymmetricTensor<4, 3> &
    HillPlasticity::hill_tensor() const
    {
      return hill;
    }


    const MaterialParameters &
    HillPlasticity::get_parameters() const
    {
      return parameters;
    }


    bool
    HillPlasticity::update(const MaterialPointState    &old_state,
                           const SymmetricTensor<2, 3> &strain_increment,
                           MaterialPointState          &new_state,
                           SymmetricTensor<4, 3>       &consistent_tangent,
                           bool                        &plastic) const
    {
      const double mu = shear_modulus;

      // Elastic predictor: sigma_trial = sigma_n + C : d_eps.
      const double          volumetric = lame_lambda * trace(strain_increment);
      SymmetricTensor<2, 3> stress_trial = old_state.stress;
      for (unsigned int I = 0; I < 6; ++I)
        stress_trial.access_raw_entry(I)
          += 2. * mu * strain_increment.access_raw_entry(I)
             + (I < 3 ? volumetric : 0.);
      const SymmetricTensor<2, 3> xi_trial
        = stress_trial - old_state.back_stress;

      const double sigma_bar_trial = equivalent_stress(xi_trial);
      double       Y_n, dY_n;
      swift(old_state.equivalent_plastic_strain, Y_n, dY_n);
      plastic = false;
      if (!std::isfinite(sigma_bar_trial) || !std::isfinite(Y_n))
        return false;

      if (sigma_bar_trial - Y_n <= yield_tolerance * Y_n)
      {
        new_state.stress      = stress_trial;
        new_state.back_stress = old_state.back_stress;
        new_state.equivalent_plastic_strain
          = old_state.equivalent_plastic_strain;
        consistent_tangent = elasticity;
        return true;
      }
      plastic = true;

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
        swift(epbar_n + gamma * sigma_bar, Y, dY);
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
