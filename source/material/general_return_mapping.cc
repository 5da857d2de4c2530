// The return mapping of ElastoPlasticity for a smooth, non-quadratic
// criterion (Yld2004-18p; doc/theory_material.md §4): Newton on the full
// closest-point-projection system in Kelvin coordinates with a backtracking
// line search, and the exact algorithmic tangent from the Hessian of the
// equivalent stress at the converged state.
#include <cmath>
#include <deepdraw/material/elasto_plasticity.h>
#include <deepdraw/material/kelvin.h>

namespace deepdraw
{
  namespace material
  {
    using dealii::SymmetricTensor;
    using kelvin::Matrix;
    using kelvin::Vector;

    namespace
    {
      // Converged when |f| <= residual_tolerance Y (as for Hill'48, so that
      // a converged state re-evaluated with a zero increment is elastic)
      // and |R| <= flow_tolerance max(Y, |xi_trial|); both lie far above
      // the round-off of the residuals (~1e-15 of these scales).
      constexpr double       residual_tolerance = 1e-13;
      constexpr double       flow_tolerance     = 1e-12;
      constexpr unsigned int max_iterations     = 100;
      constexpr unsigned int max_backtracks     = 40;
      // Armijo constant of the line search on the merit |R|^2/2 + f^2/2.
      constexpr double sufficient_decrease = 1e-4;

      // One point (xi, Delta lambda) of the local Newton iteration.
      struct Iterate
      {
        Vector xi;
        double dlambda;
        double sigma_bar, Y, dY;
        Vector n; // d sigma_bar / d xi
        Matrix H; // d^2 sigma_bar / d xi^2
        Vector R; // xi - xi_trial + beta Delta lambda n
        double f; // sigma_bar - Y
        double merit;
      };

      // Cholesky factor of A = I + beta Delta lambda H (positive definite:
      // H is positive semi-definite for a convex sigma_bar); false if it
      // is not.
      bool
      factorise(const Iterate &s, const double beta, Matrix &A)
      {
        for (unsigned int I = 0; I < 6; ++I)
          for (unsigned int J = 0; J < 6; ++J)
            A[I][J] = (I == J ? 1. : 0.) + beta * s.dlambda * s.H[I][J];
        return kelvin::cholesky(A);
      }

      // Newton correction from the Schur complement of the Jacobian
      // [[A, beta n], [n^T, -Y']] (§4).
      bool
      newton_direction(const Iterate &s,
                       const double   beta,
                       Vector        &d_xi,
                       double        &d_dlambda)
      {
        Matrix A;
        if (!factorise(s, beta, A))
          return false;
        const Vector u = kelvin::solve(A, s.R);
        const Vector v = kelvin::solve(A, s.n);
        d_dlambda
          = (s.f - kelvin::dot(s.n, u)) / (beta * kelvin::dot(s.n, v) + s.dY);
        for (unsigned int I = 0; I < 6; ++I)
          d_xi[I] = -u[I] - beta * d_dlambda * v[I];
        return true;
      }

      // Moves `current` along the Newton direction: Delta lambda stays
      // positive (Y(epbar) need not exist below epbar_n), then the step is
      // halved until the merit decreases enough (the Newton direction is a
      // descent direction for it). False if no step is accepted.
      template <typename Evaluate>
      bool
      line_search(Iterate        &current,
                  const Vector   &d_xi,
                  const double    d_dlambda,
                  const Evaluate &evaluate)
      {
        double alpha = 1.;
        if (current.dlambda + d_dlambda < 0.)
          alpha = 0.5 * current.dlambda / -d_dlambda;
        Iterate trial;
        for (unsigned int b = 0; b < max_backtracks; ++b, alpha *= 0.5)
        {
          for (unsigned int I = 0; I < 6; ++I)
            trial.xi[I] = current.xi[I] + alpha * d_xi[I];
          trial.dlambda = current.dlambda + alpha * d_dlambda;
          if (evaluate(trial)
              && trial.merit
                   <= (1. - 2. * sufficient_decrease * alpha) * current.merit)
          {
            current = trial;
            return true;
          }
        }
        return false;
      }

      // Exact algorithmic tangent at the converged state s (§4), with
      // A^{-1} = (I + beta dl H)^{-1}, b = A^{-1} n, P = I - 1(x)1/3:
      //   T = K 1(x)1 + (2 mu / beta) P (k I + 2 mu A^{-1}) P
      //       - 4 mu^2 b (x) b / (beta n.b + Y').
      bool
      algorithmic_tangent(const Iterate &s,
                          const double   K,
                          const double   mu,
                          const double   k,
                          Matrix        &T)
      {
        const double beta = 2. * mu + k;
        Matrix       A, A_inverse, P;
        if (!factorise(s, beta, A))
          return false;
        for (unsigned int J = 0; J < 6; ++J)
        {
          Vector e{};
          e[J]                = 1.;
          const Vector column = kelvin::solve(A, e);
          for (unsigned int I = 0; I < 6; ++I)
            A_inverse[I][J] = column[I];
        }
        const Vector b     = kelvin::solve(A, s.n);
        const double kappa = 4. * mu * mu / (beta * kelvin::dot(s.n, b) + s.dY);
        for (unsigned int I = 0; I < 6; ++I)
          for (unsigned int J = 0; J < 6; ++J)
            P[I][J] = (I == J ? 1. : 0.) - (I < 3 && J < 3 ? 1. / 3. : 0.);
        for (unsigned int I = 0; I < 6; ++I)
          for (unsigned int J = 0; J < 6; ++J)
          {
            double PAP = 0.; // (P A^{-1} P)_IJ
            for (unsigned int M = 0; M < 6; ++M)
              for (unsigned int N = 0; N < 6; ++N)
                PAP += P[I][M] * A_inverse[M][N] * P[N][J];
            T[I][J] = (I < 3 && J < 3 ? K : 0.)
                      + 2. * mu / beta * (k * P[I][J] + 2. * mu * PAP)
                      - kappa * b[I] * b[J];
          }
        // A^{-1} is symmetric up to round-off; T exactly.
        for (unsigned int I = 0; I < 6; ++I)
          for (unsigned int J = 0; J < I; ++J)
            T[I][J] = T[J][I] = 0.5 * (T[I][J] + T[J][I]);
        return true;
      }
    } // namespace


    bool
    ElastoPlasticity::return_mapping_general(
      const MaterialPointState    &old_state,
      const SymmetricTensor<2, 3> &xi_trial_tensor,
      MaterialPointState          &new_state,
      SymmetricTensor<4, 3>       &consistent_tangent) const
    {
      const double mu = shear_modulus, k = parameters.prager_modulus;
      const double beta     = 2. * mu + k;
      const double epbar_n  = old_state.equivalent_plastic_strain;
      const Vector xi_trial = kelvin::from_tensor(xi_trial_tensor);

      // The residuals of §4: R = xi - xi_trial + beta Delta lambda n(xi)
      // (flow rule with C : n = 2 mu n and Prager) and f = sigma_bar - Y.
      const auto evaluate = [&](Iterate &s)
      {
        s.sigma_bar = yld2004.evaluate(s.xi, s.n, &s.H);
        hardening.evaluate(epbar_n + s.dlambda, s.Y, s.dY);
        for (unsigned int I = 0; I < 6; ++I)
          s.R[I] = s.xi[I] - xi_trial[I] + beta * s.dlambda * s.n[I];
        s.f     = s.sigma_bar - s.Y;
        s.merit = 0.5 * (kelvin::dot(s.R, s.R) + s.f * s.f);
        return std::isfinite(s.merit);
      };

      // From the trial state: the first step is the cutting-plane step.
      Iterate current;
      current.xi      = xi_trial;
      current.dlambda = 0.;
      if (!evaluate(current))
        return false;
      const double scale = std::sqrt(kelvin::dot(xi_trial, xi_trial));
      for (unsigned int iteration = 0;; ++iteration)
      {
        if (std::abs(current.f) <= residual_tolerance * current.Y
            && std::sqrt(kelvin::dot(current.R, current.R))
                 <= flow_tolerance * std::max(current.Y, scale))
          break;
        Vector d_xi;
        double d_dlambda;
        if (iteration == max_iterations
            || !newton_direction(current, beta, d_xi, d_dlambda)
            || !line_search(current, d_xi, d_dlambda, evaluate))
          return false;
      }

      // New state: X = X_n + k Delta lambda n, sigma = X + xi,
      // epbar = epbar_n + Delta lambda (sigma_bar homogeneous of degree 1).
      new_state.back_stress = old_state.back_stress;
      for (unsigned int I = 0; I < 6; ++I)
        new_state.back_stress.access_raw_entry(I)
          += k * current.dlambda * current.n[I] / kelvin::weight(I);
      new_state.stress = new_state.back_stress + kelvin::to_tensor(current.xi);
      new_state.equivalent_plastic_strain = epbar_n + current.dlambda;

      Matrix T;
      if (!algorithmic_tangent(current, bulk_modulus, mu, k, T))
        return false;
      kelvin::to_tensor(T, consistent_tangent);
      return true;
    }
  } // namespace material
} // namespace deepdraw
