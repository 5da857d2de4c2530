// The numeric entries of subsection Formability and of its subsection
// Marciniak-Kuczynski as tables: name, allowed range, documentation and the
// member that holds the value. Declaring, parsing and checking all read the
// same table, so that the Pattern, the check and the message cannot
// diverge.
#ifndef deepdraw_formability_number_entries_h
#define deepdraw_formability_number_entries_h

#include <deepdraw/formability/fld_zone.h>
#include <deepdraw/formability/marciniak_kuczynski.h>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace deepdraw
{
  namespace formability
  {
    struct NumberEntry
    {
      std::string name;
      double     *value;
      double      low, high;
      bool        low_included, high_included;
      // The value's symbol in the range ("f0": "0 < f0 <= 1").
      std::string symbol;
      std::string documentation;

      // "0 < f0 <= 1".
      std::string
      range() const;

      // In the range (false for NaN).
      bool
      contains(double x) const;
    };

    std::vector<NumberEntry>
    number_entries(MarciniakKuczynskiParameters &parameters);

    std::vector<NumberEntry>
    number_entries(FldZoneParameters &parameters);

    // Declares each entry in the current subsection, with its value as the
    // default and the closed range as the Pattern.
    void
    declare_number_entries(dealii::ParameterHandler       &prm,
                           const std::vector<NumberEntry> &entries);

    // Reads each entry of the current subsection into its member.
    void
    parse_number_entries(dealii::ParameterHandler       &prm,
                         const std::vector<NumberEntry> &entries);

    // InputError "Invalid value V of <prefix><name>: allowed values are
    // <range> (<documentation>)." for the first value outside its range.
    void
    validate_number_entries(const std::vector<NumberEntry> &entries,
                            const std::string              &prefix);
  } // namespace formability
} // namespace deepdraw

#endif
