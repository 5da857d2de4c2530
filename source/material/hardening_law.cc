#include <algorithm>
#include <cmath>
#include <deepdraw/material/hardening_law.h>

namespace deepdraw
{
  namespace material
  {
    HardeningLaw::HardeningLaw(const MaterialParameters &parameters)
        : type(parameters.hardening_law)
        , swift_coefficient(parameters.swift_coefficient)
        , swift_prestrain(parameters.swift_prestrain)
        , swift_exponent(parameters.swift_exponent)
        , voce_A(parameters.voce_A)
        , voce_B(parameters.voce_B)
        , voce_C(parameters.voce_C)
    {
      const auto &table = parameters.hardening_table;
      for (const auto &[strain, stress] : table)
      {
        table_strains.push_back(strain);
        table_stresses.push_back(stress);
      }
      for (unsigned int k = 0; k < table.size(); ++k)
      {
        // Segment k runs from point k to point k + 1; past the last point
        // the last segment's slope continues (doc/theory_material.md §1.3).
        const unsigned int s = std::min<unsigned int>(k, table.size() - 2);
        table_slopes.push_back(table.size() < 2
                                 ? 0.
                                 : (table[s + 1].second - table[s].second)
                                     / (table[s + 1].first - table[s].first));
      }
    }


    void
    HardeningLaw::evaluate(const double epbar, double &Y, double &dY) const
    {
      switch (type)
      {
        case HardeningLawType::swift:
        {
          // The arithmetic of the reference model, unchanged (Hill'48
          // results stay identical to the last bit).
          const double strain = swift_prestrain + epbar;
          Y  = swift_coefficient * std::pow(strain, swift_exponent);
          dY = swift_exponent * Y / strain;
          return;
        }
        case HardeningLawType::voce:
        {
          const double decay = voce_B * std::exp(-voce_C * epbar);
          Y                  = voce_A - decay;
          dY                 = voce_C * decay;
          return;
        }
        case HardeningLawType::tabulated:
        {
          // The segment whose start is the last point <= epbar (the first
          // one below 0, which only a failing Newton iterate can reach).
          const auto next = std::upper_bound(table_strains.begin(),
                                             table_strains.end(),
                                             epbar);
          const auto k    = std::max<long>(next - table_strains.begin() - 1, 0);
          dY              = table_slopes[k];
          Y               = table_stresses[k] + dY * (epbar - table_strains[k]);
          return;
        }
      }
    }


    double
    HardeningLaw::yield_stress(const double epbar) const
    {
      double Y, dY;
      evaluate(epbar, Y, dY);
      return Y;
    }


    double
    HardeningLaw::hardening_modulus(const double epbar) const
    {
      double Y, dY;
      evaluate(epbar, Y, dY);
      return dY;
    }
  } // namespace material
} // namespace deepdraw
