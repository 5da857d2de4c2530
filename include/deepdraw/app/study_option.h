// One `--study "Subsection/Parameter = v1, v2, ..."` option of deepdraw
// (doc/user_guide.md §4.2): the parameter a refinement study varies and its
// values, one run per value. Several options of the same length vary
// together. Checked against the declared parameters before anything is run
// or written (doc/decisions.md D41).
#ifndef deepdraw_app_study_option_h
#define deepdraw_app_study_option_h

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace app
  {
    using namespace dealii;

    struct StudyVariable
    {
      // The enclosing subsections, outermost first, and the entry.
      std::vector<std::string> subsections;
      std::string              entry;
      // One value per run, as text (trimmed, never empty).
      std::vector<std::string> values;

      // "Subsection/.../Parameter", as the user wrote it (trimmed).
      std::string
      name() const;
    };

    // The syntax of one option; throws InputError quoting the option.
    StudyVariable
    parse_study_option(const std::string &text);

    // Every option of a study: the syntax of each, each a declared parameter
    // of prm (which is only read: entered and left), none given twice, not
    // Output/Output directory (the study sets it), all of the same number of
    // values. Throws InputError naming the offending option.
    std::vector<StudyVariable>
    parse_study_options(const std::vector<std::string> &texts,
                        ParameterHandler               &prm);

    // Whether subsections/entry is a declared entry of prm.
    bool
    is_declared(ParameterHandler               &prm,
                const std::vector<std::string> &subsections,
                const std::string              &entry);

    // Sets the variable's value of run `run` in prm; throws (deal.II) if
    // the value does not match the entry's pattern.
    void
    set_value(ParameterHandler    &prm,
              const StudyVariable &variable,
              unsigned int         run);
  } // namespace app
} // namespace deepdraw

#endif
