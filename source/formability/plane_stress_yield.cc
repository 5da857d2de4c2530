// Hill'48 and Yld2004-18p in plane stress and the stress state of a given
// strain ratio (doc/theory_formability.md §3).
#include <cmath>
#include <deal.II/base/numbers.h>
#include <deepdraw/formability/plane_stress_yield.h>
#include <deepdraw/io/value_check.h>
#include <deepdraw/material/kelvin.h>

namespace deepdraw
{
  namespace formability
  {
    HillPlaneStress::HillPlaneStress(
      const material::MaterialParameters &parameters)
    {
      parameters.validate();
      F = parameters.hill_F;
      G = parameters.hill_G;
      H = parameters.hill_H;
      N = parameters.hill_N;
    }


    double
    HillPlaneStress::equivalent_stress(const PlaneTensor &s) const
    {
      const double squared
        = (G + H) * s[0][0] * s[0][0] - 2. * H * s[0][0] * s[1][1]
          + (F + H) * s[1][1] * s[1][1] + 2. * N * s[0][1] * s[0][1];
      // G + H, F + H > 0 and N > 0 (validated) make the form positive
      // definite; max() only guards round-off at s = 0.
      return std::sqrt(std::max(squared, 0.));
    }


    PlaneTensor
    HillPlaneStress::gradient(const PlaneTensor &s) const
    {
      const double sigma_bar = equivalent_stress(s);
      PlaneTensor  g;
      g[0][0] = ((G + H) * s[0][0] - H * s[1][1]) / sigma_bar;
      g[1][1] = ((F + H) * s[1][1] - H * s[0][0]) / sigma_bar;
      // d(sigma_bar^2)/d s12 = 4 N s12 and the full contraction counts the
      // shear component twice: g12 = N s12 / sigma_bar.
      g[0][1] = N * s[0][1] / sigma_bar;
      return g;
    }


    namespace
    {
      const material::MaterialParameters &
      validated(const material::MaterialParameters &parameters)
      {
        parameters.validate();
        return parameters;
      }

      // The 3D stress of a plane stress: sigma_33 = sigma_13 = sigma_23 = 0.
      dealii::SymmetricTensor<2, 3>
      three_dimensional(const PlaneTensor &s)
      {
        dealii::SymmetricTensor<2, 3> t;
        t[0][0] = s[0][0];
        t[1][1] = s[1][1];
        t[0][1] = s[0][1];
        return t;
      }
    } // namespace


    Yld2004PlaneStress::Yld2004PlaneStress(
      const material::MaterialParameters &parameters)
        : criterion(validated(parameters))
    {
    }


    double
    Yld2004PlaneStress::equivalent_stress(const PlaneTensor &s) const
    {
      return criterion.equivalent_stress(three_dimensional(s));
    }


    PlaneTensor
    Yld2004PlaneStress::gradient(const PlaneTensor &s) const
    {
      // The Kelvin gradient n has n_12 = sqrt2 d sigma_bar / d sigma_12
      // (one shear coordinate); kelvin::to_tensor divides it by sqrt2, the
      // tensor component g_12 with d sigma_bar = g : d sigma counting the
      // shear twice. g_13 = g_23 = 0 (orthotropy); g_33 = -(g_11 + g_22)
      // is the thickness strain rate that the analysis takes from volume
      // constancy.
      material::kelvin::Vector n;
      criterion.evaluate(material::kelvin::from_tensor(three_dimensional(s)),
                         n,
                         nullptr);
      const dealii::SymmetricTensor<2, 3> g3 = material::kelvin::to_tensor(n);
      PlaneTensor                         g;
      g[0][0] = g3[0][0];
      g[1][1] = g3[1][1];
      g[0][1] = g3[0][1];
      return g;
    }


    std::unique_ptr<PlaneStressYield>
    create_plane_stress_yield(const material::MaterialParameters &parameters)
    {
      if (parameters.yield_criterion == material::YieldCriterion::yld2004_18p)
        return std::make_unique<Yld2004PlaneStress>(parameters);
      return std::make_unique<HillPlaneStress>(parameters);
    }


    std::string
    plane_stress_yield_name(const material::MaterialParameters &parameters)
    {
      if (parameters.yield_criterion == material::YieldCriterion::yld2004_18p)
        return "Yld2004-18p a = "
               + io::number_text(parameters.yld2004_exponent);
      return "Hill'48";
    }


    double
    uniaxial_strain_ratio(const PlaneStressYield &yield)
    {
      PlaneTensor uniaxial;
      uniaxial[0][0]      = 1.;
      const PlaneTensor g = yield.gradient(uniaxial);
      return g[1][1] / g[0][0];
    }


    namespace
    {
      // The unit direction at angle theta in the (s11, s22) plane.
      PlaneTensor
      direction(const double theta)
      {
        PlaneTensor s;
        s[0][0] = std::cos(theta);
        s[1][1] = std::sin(theta);
        return s;
      }

      // Bisection for the sign change of f on [low, high], f(low) <= 0 <
      // f(high), to the round-off of the angle.
      template <typename Function>
      double
      bisect(const Function &f, double low, double high)
      {
        for (unsigned int k = 0; k < 200 && high - low > 1e-15; ++k)
        {
          const double middle            = 0.5 * (low + high);
          (f(middle) <= 0. ? low : high) = middle;
        }
        return 0.5 * (low + high);
      }
    } // namespace


    PlaneTensor
    stress_for_strain_ratio(const PlaneStressYield &yield, const double rho)
    {
      // Along theta from uniaxial tension in direction 1 (theta = 0) the
      // normal of a convex locus turns monotonically: rho(theta) increases
      // from the uniaxial ratio and tends to +infinity where g11 = 0
      // (plane strain along direction 2), at theta* <= pi/2.
      const auto minus_g11 = [&](const double theta)
      { return -yield.gradient(direction(theta))[0][0]; };
      const double pi = dealii::numbers::PI;
      const double theta_limit
        = minus_g11(pi / 2.) <= 0. ? pi / 2. : bisect(minus_g11, 0., pi / 2.);
      // sign(g22 - rho g11) = sign(rho(theta) - rho) where g11 > 0.
      const auto excess = [&](const double theta)
      {
        const PlaneTensor g = yield.gradient(direction(theta));
        return g[1][1] - rho * g[0][0];
      };
      const double theta
        = excess(0.) >= 0. ? 0. : bisect(excess, 0., theta_limit);
      const PlaneTensor s = direction(theta);
      return s / yield.equivalent_stress(s);
    }
  } // namespace formability
} // namespace deepdraw
