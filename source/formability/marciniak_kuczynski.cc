// The M-K analysis: the integration of one strain path with one groove
// (doc/theory_formability.md §4.2-4.4) and the search over groove angles.
#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/numbers.h>
#include <deepdraw/formability/marciniak_kuczynski.h>
#include <deepdraw/formability/number_entries.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/value_check.h>

namespace deepdraw
{
  namespace formability
  {
    namespace
    {
      constexpr double degree = dealii::numbers::PI / 180.;
      // The groove strain at which a path is given up as not localising.
      constexpr double maximum_groove_strain = 10.;

      // InputError "the Marciniak-Kuczynski analysis <what> for the strain
      // ratio <rho><details>".
      [[noreturn]] void
      fail(const double       rho,
           const std::string &what,
           const std::string &details)
      {
        throw InputError("the Marciniak-Kuczynski analysis " + what
                         + " for the strain ratio " + io::number_text(rho)
                         + details);
      }

      using Vector4 = std::array<double, 4>;

      // Solves A x = b by Gaussian elimination with partial pivoting; false
      // if A is singular to working precision.
      bool
      solve(std::array<Vector4, 4> A, Vector4 b, Vector4 &x)
      {
        for (unsigned int k = 0; k < 4; ++k)
        {
          unsigned int pivot = k;
          for (unsigned int i = k + 1; i < 4; ++i)
            if (std::abs(A[i][k]) > std::abs(A[pivot][k]))
              pivot = i;
          if (!(std::abs(A[pivot][k]) > 1e-300))
            return false;
          std::swap(A[k], A[pivot]);
          std::swap(b[k], b[pivot]);
          for (unsigned int i = k + 1; i < 4; ++i)
          {
            const double factor = A[i][k] / A[k][k];
            for (unsigned int j = k; j < 4; ++j)
              A[i][j] -= factor * A[k][j];
            b[i] -= factor * b[k];
          }
        }
        for (int i = 3; i >= 0; --i)
        {
          double sum = b[i];
          for (unsigned int j = i + 1; j < 4; ++j)
            sum -= A[i][j] * x[j];
          x[i] = sum / A[i][i];
        }
        return true;
      }

      // Components (nn, nt, tt) of s in the groove frame n = (cos psi,
      // sin psi), t = (-sin psi, cos psi).
      std::array<double, 3>
      groove_components(const PlaneTensor &s, const double psi)
      {
        const double c = std::cos(psi), d = std::sin(psi);
        return {{c * c * s[0][0] + 2. * c * d * s[0][1] + d * d * s[1][1],
                 c * d * (s[1][1] - s[0][0]) + (c * c - d * d) * s[0][1],
                 d * d * s[0][0] - 2. * c * d * s[0][1] + c * c * s[1][1]}};
      }

      // The tensor nn n(x)n + nt (n(x)t + t(x)n) + tt t(x)t in the material
      // axes.
      PlaneTensor
      from_groove_components(const double nn,
                             const double nt,
                             const double tt,
                             const double psi)
      {
        const double c = std::cos(psi), d = std::sin(psi);
        PlaneTensor  s;
        s[0][0] = nn * c * c - 2. * nt * c * d + tt * d * d;
        s[1][1] = nn * d * d + 2. * nt * c * d + tt * c * c;
        s[0][1] = (nn - tt) * c * d + nt * (c * c - d * d);
        return s;
      }


      // One strain path (zone a at the unit stress s_a, strain direction
      // g_a) with one initial groove angle psi0.
      class GroovePath
      {
      public:
        GroovePath(const PlaneStressYield             &yield,
                   const MkHardening                  &hardening,
                   const MarciniakKuczynskiParameters &parameters,
                   const PlaneTensor                  &s_a,
                   const double                        psi0)
            : yield(yield)
            , hardening(hardening)
            , f0(parameters.imperfection)
            , s_a(s_a)
            , g_a(yield.gradient(s_a))
            , psi0(psi0)
            , saturation(hardening.saturation_stress())
        {
          // Start: the groove at the stress of the sheet, the sheet carrying
          // f0 times the groove's stress (equilibrium of the thinner groove).
          const std::array<double, 3> s = groove_components(s_a, psi0);
          x                             = {{s[0], s[1], s[2], f0}};
        }

        // Advances by a groove equivalent strain increment delta (halved
        // where Newton fails); returns zone a's equivalent strain increment
        // over the groove's, or -1 if no step converged.
        double
        advance(double delta)
        {
          for (unsigned int cut = 0; cut < 20; ++cut, delta *= 0.5)
            if (newton(delta))
            {
              const double d_a = accept(delta);
              return d_a / delta;
            }
          return -1.;
        }

        double
        major_strain() const
        {
          return eps_a[0][0];
        }

        double
        groove_strain() const
        {
          return epbar_b;
        }

        // Whether a trial asked zone a for a stress at or above the
        // saturation of the hardening law (no strain carries it).
        bool
        saturation_reached() const
        {
          return saturated;
        }

      private:
        // The state at the end of a trial step, for the unknowns x =
        // (sigma_b in the groove frame, zone a's stress) / Y_b
        // (doc/theory_formability.md §4.3).
        struct Trial
        {
          double      d_epbar_a;
          PlaneTensor eps_a, eps_b;
        };

        Vector4
        residual(const double delta, const Vector4 &y, Trial &trial) const
        {
          const double Y_b      = hardening.yield_stress(epbar_b + delta);
          const double stress_a = y[3] * Y_b;
          // Zone a is rigid below its current yield stress; at or above the
          // saturation the inverse is +infinity and the residual not finite.
          saturated       = saturated || stress_a >= saturation;
          trial.d_epbar_a = stress_a > hardening.yield_stress(epbar_a)
                              ? hardening.equivalent_strain(stress_a) - epbar_a
                              : 0.;
          trial.eps_a     = eps_a + trial.d_epbar_a * g_a;
          // The groove follows the material line of zone a (eq. 4.2).
          const double psi
            = std::atan2(std::sin(psi0) * std::exp(trial.eps_a[0][0]),
                         std::cos(psi0) * std::exp(trial.eps_a[1][1]));
          const PlaneTensor sigma_b
            = Y_b * from_groove_components(y[0], y[1], y[2], psi);
          const PlaneTensor g_b = yield.gradient(sigma_b);
          trial.eps_b           = eps_b + delta * g_b;
          // t_b / t_a = f0 exp(eps3_b - eps3_a), eps3 = -trace (eq. 4.5).
          const double thickness_ratio
            = f0 * std::exp(trace(trial.eps_a) - trace(trial.eps_b));
          const std::array<double, 3> a    = groove_components(s_a, psi);
          const double                tt_b = groove_components(g_b, psi)[2];
          const double                tt_a = groove_components(g_a, psi)[2];
          return {{yield.equivalent_stress(sigma_b) / Y_b - 1.,
                   thickness_ratio * y[0] - y[3] * a[0],
                   thickness_ratio * y[1] - y[3] * a[1],
                   tt_b - trial.d_epbar_a / delta * tt_a}};
        }

        // Newton with a forward-difference Jacobian on the four unknowns;
        // on success x holds the solution.
        bool
        newton(const double delta)
        {
          Vector4 y = x;
          Trial   trial;
          // The last Newton step changed no unknown beyond round-off: at
          // large strains zone a's increment is the difference of two
          // nearly equal strains and R4 cannot fall below ~eps/delta.
          bool round_off = false;
          for (unsigned int iteration = 0; iteration < 40; ++iteration)
          {
            const Vector4 r    = residual(delta, y, trial);
            double        size = 0.;
            for (const double value : r)
              size = std::max(size, std::abs(value));
            if (!std::isfinite(size))
              return false;
            if (size < 1e-10 || (size < 1e-6 && round_off))
            {
              x = y;
              return true;
            }
            std::array<Vector4, 4> J;
            for (unsigned int j = 0; j < 4; ++j)
            {
              Vector4      z = y;
              const double h = 1e-7 * std::max(std::abs(y[j]), 1e-3);
              z[j] += h;
              const Vector4 r_h = residual(delta, z, trial);
              for (unsigned int i = 0; i < 4; ++i)
                J[i][j] = (r_h[i] - r[i]) / h;
            }
            Vector4 step;
            if (!solve(J, r, step))
              return false;
            round_off = true;
            for (unsigned int j = 0; j < 4; ++j)
            {
              round_off
                = round_off
                  && std::abs(step[j]) < 1e-13 * std::max(std::abs(y[j]), 1.);
              y[j] -= step[j];
            }
          }
          return false;
        }

        double
        accept(const double delta)
        {
          Trial trial;
          residual(delta, x, trial);
          epbar_a += trial.d_epbar_a;
          epbar_b += delta;
          eps_a = trial.eps_a;
          eps_b = trial.eps_b;
          return trial.d_epbar_a;
        }

        const PlaneStressYield &yield;
        const MkHardening      &hardening;
        const double            f0;
        const PlaneTensor       s_a, g_a;
        const double            psi0;
        const double            saturation;
        mutable bool            saturated = false;

        double      epbar_a = 0., epbar_b = 0.;
        PlaneTensor eps_a, eps_b;
        Vector4     x;
      };
    } // namespace


    void
    MarciniakKuczynskiParameters::validate() const
    {
      MarciniakKuczynskiParameters copy = *this;
      validate_number_entries(number_entries(copy),
                              "Formability/Marciniak-Kuczynski/");
    }


    MarciniakKuczynski::MarciniakKuczynski(
      const PlaneStressYield             &yield,
      const MkHardening                  &hardening,
      const MarciniakKuczynskiParameters &parameters)
        : yield(yield)
        , hardening(hardening)
        , parameters(parameters)
    {
      parameters.validate();
      const std::string perfectly_plastic = hardening.without_hardening();
      if (!perfectly_plastic.empty())
        throw InputError(perfectly_plastic);
    }


    MkLimitPoint
    MarciniakKuczynski::limit_for_groove_angle(const double rho,
                                               const double groove_angle,
                                               const double bound) const
    {
      const double inverse_factor = 1. / parameters.localisation_factor;
      GroovePath   path(yield,
                      hardening,
                      parameters,
                      stress_for_strain_ratio(yield, rho),
                      groove_angle * degree);
      MkLimitPoint point{rho,
                         std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::infinity(),
                         groove_angle};
      // Armed once zone a deforms at more than 1/factor of the groove's
      // rate, so that the rigid start of zone a (its yield stress is not
      // reached until the groove has hardened by 1/f0) is not taken for
      // localisation (doc/theory_formability.md §4.4).
      bool   armed = false;
      double rate = 0., major = 0.;
      while (path.groove_strain() < maximum_groove_strain
             && path.major_strain() <= bound)
      {
        // Zone a's equivalent strain increment over the groove's.
        const double new_rate = path.advance(parameters.strain_increment);
        if (new_rate < 0. && path.saturation_reached())
          fail(rho,
               "reached the saturation stress of the hardening law ("
                 + hardening.saturation_source() + ")",
               " and the groove angle " + io::number_text(groove_angle)
                 + " degrees before the groove localised: no strain "
                   "carries a larger stress, and the analysis cannot "
                   "continue (D171; with Formability/Marciniak-Kuczynski/"
                   "Imperfection f0 = "
                 + io::number_text(parameters.imperfection)
                 + " the groove did not localise before it saturated)");
        if (new_rate < 0.)
          fail(rho,
               "did not converge",
               " and the groove angle " + io::number_text(groove_angle)
                 + " degrees; try a smaller Formability/Marciniak-Kuczynski/"
                   "Strain increment");
        if (armed && new_rate <= inverse_factor)
        {
          // Linear in the rate between the two steps.
          const double w     = (rate - inverse_factor) / (rate - new_rate);
          point.major_strain = major + w * (path.major_strain() - major);
          // The path is proportional: eps2 = rho eps1 up to the bisection
          // of the stress state (1e-15).
          point.minor_strain = rho * point.major_strain;
          return point;
        }
        armed = armed || new_rate > inverse_factor;
        rate  = new_rate;
        major = path.major_strain();
      }
      return point;
    }


    MkLimitPoint
    MarciniakKuczynski::limit_point(const double rho) const
    {
      std::vector<double> angles = {0.};
      if (rho >= 1.)
        angles.push_back(90.);
      if (rho < 0.)
      {
        for (double angle = parameters.groove_angle_step; angle < 45. + 1e-9;
             angle += parameters.groove_angle_step)
          angles.push_back(std::min(angle, 45.));
        // Nearest first to Hill's zero-extension direction tan^2 psi = -rho
        // carried back along the homogeneous strain to Hill's limit
        // eps1 = n / (1 + rho) (eq. 4.2): a low limit found early bounds the
        // other angles' integrations.
        const double estimate
          = std::atan(
              std::sqrt(-rho)
              * std::exp(-(1. - rho) * hardening.necking_strain() / (1. + rho)))
            / degree;
        std::stable_sort(angles.begin(),
                         angles.end(),
                         [&](const double a, const double b) {
                           return std::abs(a - estimate)
                                  < std::abs(b - estimate);
                         });
      }
      MkLimitPoint best = limit_for_groove_angle(rho, angles[0]);
      for (unsigned int k = 1; k < angles.size(); ++k)
      {
        const MkLimitPoint point
          = limit_for_groove_angle(rho, angles[k], best.major_strain);
        if (point.major_strain < best.major_strain)
          best = point;
      }
      if (rho < 0.)
        best = refine_groove_angle(rho, best);
      if (!std::isfinite(best.major_strain))
        fail(rho,
             "found no localisation",
             " before the groove's equivalent strain reached "
               + io::number_text(maximum_groove_strain)
               + " (Formability/Marciniak-Kuczynski/Imperfection f0 = "
               + io::number_text(parameters.imperfection)
               + "; f0 = 1 is a sheet without imperfection, use f0 < 1)");
      return best;
    }


    MkLimitPoint
    MarciniakKuczynski::refine_groove_angle(const double        rho,
                                            const MkLimitPoint &grid_best) const
    {
      // Golden-section search within one grid step of the best grid angle:
      // the limit strain is smooth and has one minimum there.
      const double ratio = 0.5 * (std::sqrt(5.) - 1.);
      double       low
        = std::max(grid_best.groove_angle - parameters.groove_angle_step, 0.);
      double high
        = std::min(grid_best.groove_angle + parameters.groove_angle_step, 45.);
      MkLimitPoint best     = grid_best;
      const auto   evaluate = [&](const double angle)
      {
        const MkLimitPoint point = limit_for_groove_angle(rho, angle);
        if (point.major_strain < best.major_strain)
          best = point;
        return point.major_strain;
      };
      // Interior points a < b; the better one is kept for the next bracket.
      double a = high - ratio * (high - low), b = low + ratio * (high - low);
      double f_a = evaluate(a), f_b = evaluate(b);
      while (high - low > 0.02)
      {
        const bool   left   = f_a <= f_b; // the minimum is in [low, b]
        const double kept   = left ? a : b;
        const double f_kept = left ? f_a : f_b;
        (left ? high : low) = left ? b : a;
        const double fresh
          = left ? high - ratio * (high - low) : low + ratio * (high - low);
        const double f_fresh = evaluate(fresh);
        a                    = left ? fresh : kept;
        f_a                  = left ? f_fresh : f_kept;
        b                    = left ? kept : fresh;
        f_b                  = left ? f_kept : f_fresh;
      }
      return best;
    }


    std::vector<double>
    MarciniakKuczynski::strain_ratios() const
    {
      const double        uniaxial = uniaxial_strain_ratio(yield);
      const double        step     = parameters.strain_ratio_step;
      std::vector<double> ratios   = {uniaxial};
      // Multiples of the step above the uniaxial ratio; one closer to it
      // than a quarter step is left out.
      for (long k = std::lround(std::ceil(uniaxial / step));
           k * step < 1. - 1e-9;
           ++k)
        if (k * step > uniaxial + 0.25 * step)
          ratios.push_back(k * step);
      ratios.push_back(1.);
      return ratios;
    }


    std::vector<MkLimitPoint>
    MarciniakKuczynski::limit_curve() const
    {
      std::vector<MkLimitPoint> points;
      for (const double rho : strain_ratios())
        points.push_back(limit_point(rho));
      return points;
    }
  } // namespace formability
} // namespace deepdraw
