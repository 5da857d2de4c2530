// The travels at which the thickness profiles and the earing profile are
// written: `Output/Thickness profile travels`, declared by the "thickness
// profiles" post-processor and read by it and by "earing"; and any such
// list of travels (`Formability/FLD travels` of "forming limits").
#ifndef deepdraw_postprocess_profile_travels_h
#define deepdraw_postprocess_profile_travels_h

#include <deal.II/base/parameter_handler.h>
#include <vector>

namespace deepdraw
{
  namespace postprocess
  {
    void
    declare_profile_travels(dealii::ParameterHandler &prm);

    // The travels of the parameter, checked: two travels must not give the
    // same file name (InputError).
    std::vector<double>
    parse_profile_travels(dealii::ParameterHandler &prm);

    // A list of travels in the current subsection: entry, its default and
    // documentation.
    void
    declare_travels(dealii::ParameterHandler &prm,
                    const std::string        &entry,
                    const std::string        &default_value,
                    const std::string        &documentation);

    // The travels of entry in the current subsection (whose path, as
    // messages give it, is section: "Output/"), checked: two travels must
    // not give the same file name <file_prefix><label>mm.csv (InputError).
    std::vector<double>
    parse_travels(dealii::ParameterHandler &prm,
                  const std::string        &section,
                  const std::string        &entry,
                  const std::string        &file_prefix);

    // Those up to final_load, sorted, each once.
    std::vector<double>
    travels_within(const std::vector<double> &travels, double final_load);
  } // namespace postprocess
} // namespace deepdraw

#endif
