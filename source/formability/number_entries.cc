// The numeric entries of subsection Formability (doc/user_guide.md §8).
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/formability/number_entries.h>
#include <deepdraw/io/value_check.h>

namespace deepdraw
{
  namespace formability
  {
    std::string
    NumberEntry::range() const
    {
      return io::number_text(low) + (low_included ? " <= " : " < ") + symbol
             + (high_included ? " <= " : " < ") + io::number_text(high);
    }


    bool
    NumberEntry::contains(const double x) const
    {
      return (low_included ? x >= low : x > low)
             && (high_included ? x <= high : x < high);
    }


    std::vector<NumberEntry>
    number_entries(MarciniakKuczynskiParameters &p)
    {
      return {
        {"Imperfection f0",
         &p.imperfection,
         0.,
         1.,
         false,
         true,
         "f0",
         "initial thickness of the groove over that of the sheet; 1: no "
         "imperfection, no localisation"},
        {"Groove angle step",
         &p.groove_angle_step,
         0.,
         45.,
         false,
         true,
         "step",
         "degrees, grid of initial groove angles searched on the left side "
         "(strain ratio < 0); the best one is refined to 0.02 degrees"},
        {"Strain increment",
         &p.strain_increment,
         0.,
         0.05,
         false,
         true,
         "increment",
         "equivalent plastic strain of the groove per integration step"},
        {"Localisation factor",
         &p.localisation_factor,
         1.,
         1e6,
         false,
         true,
         "factor",
         "localised when the groove's equivalent strain increment exceeds "
         "the sheet's by this factor"},
        {"Strain ratio step",
         &p.strain_ratio_step,
         0.,
         0.5,
         false,
         true,
         "step",
         "strain ratios of the curve: the material's own uniaxial ratio, "
         "then the multiples of this step up to 1 (equibiaxial)"}};
    }


    std::vector<NumberEntry>
    number_entries(FldZoneParameters &p)
    {
      return {{"Safety band",
               &p.safety_band,
               0.,
               100.,
               true,
               false,
               "band",
               "% of the limit major strain: a point less than this below "
               "the FLC is marginal"},
              {"Thinning limit",
               &p.thinning_limit,
               -10.,
               0.,
               true,
               false,
               "limit",
               "thickness strain ln(t/t0) below which a point is thinning "
               "(-0.25: 22 % thinner)"},
              {"Insufficient stretch strain",
               &p.insufficient_stretch,
               0.,
               1.,
               true,
               true,
               "s",
               "insufficient stretch where eps1 < s and eps2 > -s (true "
               "strains)"},
              {"Wrinkling minor strain",
               &p.wrinkling_minor_strain,
               0.,
               1.,
               true,
               true,
               "w",
               "wrinkling tendency where eps2 <= -w while the sheet "
               "thickens"}};
    }


    void
    declare_number_entries(dealii::ParameterHandler       &prm,
                           const std::vector<NumberEntry> &entries)
    {
      for (const NumberEntry &entry : entries)
        prm.declare_entry(entry.name,
                          io::number_text(*entry.value),
                          dealii::Patterns::Double(entry.low, entry.high),
                          entry.documentation + "; " + entry.range() + ".");
    }


    void
    parse_number_entries(dealii::ParameterHandler       &prm,
                         const std::vector<NumberEntry> &entries)
    {
      for (const NumberEntry &entry : entries)
        *entry.value = prm.get_double(entry.name);
    }


    void
    validate_number_entries(const std::vector<NumberEntry> &entries,
                            const std::string              &prefix)
    {
      for (const NumberEntry &entry : entries)
        io::require_value(entry.contains(*entry.value),
                          prefix + entry.name,
                          *entry.value,
                          entry.range() + " (" + entry.documentation + ")");
    }
  } // namespace formability
} // namespace deepdraw
