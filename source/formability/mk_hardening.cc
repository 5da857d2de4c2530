// The hardening law of the M-K analysis and its inverse
// (doc/theory_formability.md §4.6, D170).
#include <cmath>
#include <deepdraw/formability/mk_hardening.h>
#include <deepdraw/io/value_check.h>
#include <limits>

namespace deepdraw
{
  namespace formability
  {
    namespace
    {
      constexpr double infinity = std::numeric_limits<double>::infinity();
      // A law that has not reached a stress by this strain is taken as
      // saturated below it.
      constexpr double largest_strain = 1e12;
    } // namespace


    MkHardening::MkHardening(const material::MaterialParameters &p)
        : parameters((p.validate(), p))
        , law(p)
    {
    }


    double
    MkHardening::yield_stress(const double equivalent_plastic_strain) const
    {
      return law.yield_stress(equivalent_plastic_strain);
    }


    double
    MkHardening::equivalent_strain(const double stress) const
    {
      if (parameters.hardening_law != material::HardeningLawType::swift)
        return solve_equivalent_strain(stress);
      // Swift's closed form, the arithmetic of the analysis since D135 (the
      // Hill'48/Swift curve stays the same to the last bit, D170).
      return std::pow(stress / parameters.swift_coefficient,
                      1. / parameters.swift_exponent)
             - parameters.swift_prestrain;
    }


    double
    MkHardening::solve_equivalent_strain(const double stress) const
    {
      if (!(stress > law.yield_stress(0.)))
        return 0.;
      if (stress >= saturation_stress())
        return infinity;
      // A bracket [low, high] with Y(low) < stress <= Y(high).
      double low = 0., high = 1.;
      while (law.yield_stress(high) < stress)
      {
        low = high;
        high *= 2.;
        if (high > largest_strain)
          return infinity;
      }
      // Newton, kept inside the bracket: a step that leaves it, or a zero
      // slope (a flat segment of a table), is replaced by bisection. On a
      // table the Newton step from inside the right segment is exact.
      double e = high;
      for (unsigned int k = 0; k < 300; ++k)
      {
        double Y, dY;
        law.evaluate(e, Y, dY);
        const double r = Y - stress;
        if (r == 0.)
          return e;
        (r < 0. ? low : high) = e;
        double next           = dY > 0. ? e - r / dY : low - 1.;
        if (!(next > low && next < high))
          next = 0.5 * (low + high);
        if (std::abs(next - e) <= 2e-16 * std::max(std::abs(e), 1e-300)
            || high - low <= 2e-16 * high)
          return next;
        e = next;
      }
      return high;
    }


    double
    MkHardening::saturation_stress() const
    {
      using Type                            = material::HardeningLawType;
      const material::MaterialParameters &p = parameters;
      switch (p.hardening_law)
      {
        case Type::swift:
          return p.swift_exponent > 0. ? infinity : law.yield_stress(0.);
        case Type::voce:
          return p.voce_C > 0. ? p.voce_A : p.voce_A - p.voce_B;
        case Type::tabulated:
        {
          const auto &table = p.hardening_table;
          if (table.size() < 2)
            return table.front().second;
          const auto &last   = table[table.size() - 1];
          const auto &before = table[table.size() - 2];
          return last.second > before.second ? infinity : last.second;
        }
      }
      return infinity;
    }


    std::string
    MkHardening::without_hardening() const
    {
      if (saturation_stress() > law.yield_stress(0.))
        return "";
      const std::string consequence
        = " (without hardening the limit strain is zero).";
      switch (parameters.hardening_law)
      {
        case material::HardeningLawType::swift:
          return "Material/Swift exponent is 0: allowed values for a "
                 "Marciniak-Kuczynski curve are n > 0"
                 + consequence;
        case material::HardeningLawType::voce:
          return std::string(parameters.voce_B > 0. ? "Material/Voce C"
                                                    : "Material/Voce B")
                 + " is 0: allowed values for a Marciniak-Kuczynski curve "
                   "are B > 0 and C > 0"
                 + consequence;
        case material::HardeningLawType::tabulated:
          break;
      }
      return "Material/Hardening table is perfectly plastic (every stress "
             "is "
             + io::number_text(law.yield_stress(0.))
             + " MPa): a Marciniak-Kuczynski curve needs a stress that "
               "rises with the strain"
             + consequence;
    }


    double
    MkHardening::necking_strain() const
    {
      if (parameters.hardening_law == material::HardeningLawType::swift)
        return parameters.swift_exponent;
      // The uniaxial Considere strain, Y'(e) = Y(e) (n - eps0 for Swift).
      const auto excess = [&](const double e)
      {
        double Y, dY;
        law.evaluate(e, Y, dY);
        return dY - Y;
      };
      double low = 0., high = 10.;
      if (excess(low) <= 0.)
        return 0.;
      if (excess(high) > 0.)
        return high;
      for (unsigned int k = 0; k < 60; ++k)
      {
        const double middle                = 0.5 * (low + high);
        (excess(middle) > 0. ? low : high) = middle;
      }
      return 0.5 * (low + high);
    }


    std::string
    MkHardening::description() const
    {
      const material::MaterialParameters &p = parameters;
      switch (p.hardening_law)
      {
        case material::HardeningLawType::swift:
          return "Swift n = " + io::number_text(p.swift_exponent);
        case material::HardeningLawType::voce:
          return "Voce A = " + io::number_text(p.voce_A)
                 + " MPa, B = " + io::number_text(p.voce_B)
                 + " MPa, C = " + io::number_text(p.voce_C);
        case material::HardeningLawType::tabulated:
          break;
      }
      return "tabulated hardening (" + std::to_string(p.hardening_table.size())
             + " points)";
    }


    std::string
    MkHardening::saturation_source() const
    {
      const material::MaterialParameters &p = parameters;
      if (p.hardening_law == material::HardeningLawType::voce)
        return "Material/Voce A = " + io::number_text(p.voce_A) + " MPa";
      if (p.hardening_law == material::HardeningLawType::tabulated)
        return "Material/Hardening table, flat beyond its last point at "
               + io::number_text(saturation_stress()) + " MPa";
      return "Material/Swift exponent = 0";
    }
  } // namespace formability
} // namespace deepdraw
