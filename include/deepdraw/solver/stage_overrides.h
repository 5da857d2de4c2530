// A stage's own values of a subsection's numeric entries (Process/Stage N/
// Load stepping, D101; Process/Stage N/Newton, D208): declared empty, and
// where set, checked against the entry's range before they replace the
// value of the subsection at the top level.
#ifndef deepdraw_solver_stage_overrides_h
#define deepdraw_solver_stage_overrides_h

#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace solver
  {
    using namespace dealii;

    struct OverridableEntry
    {
      const char *name;
      double      low, high;
      bool        integer;
      // What the entry does, appended to "Empty: as <subsection>/<name>;
      // otherwise this stage's value. "
      const char *description;
    };

    // Patterns::Integer or Patterns::Double over [low, high].
    std::unique_ptr<Patterns::PatternBase>
    range_pattern(const OverridableEntry &entry);

    // In the current subsection (a stage slot): subsection `subsection`
    // with every entry, empty by default.
    void
    declare_overrides(ParameterHandler                    &prm,
                      const std::string                   &subsection,
                      const std::vector<OverridableEntry> &entries);

    // Calls set(name, value) for every entry that is set, after checking
    // it against its range (InputError "<prefix><subsection>/<name> =
    // '<value>': allowed are <range>, or empty").
    void
    parse_overrides(
      ParameterHandler                    &prm,
      const std::string                   &subsection,
      const std::vector<OverridableEntry> &entries,
      const std::string                   &prefix,
      const std::function<void(const std::string &, const std::string &)> &set);

    // The name of the first entry that is set, or "".
    std::string
    first_override(ParameterHandler                    &prm,
                   const std::string                   &subsection,
                   const std::vector<OverridableEntry> &entries);
  } // namespace solver
} // namespace deepdraw

#endif
