#include <deal.II/base/utilities.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/solver/stage_overrides.h>

namespace deepdraw
{
  namespace solver
  {
    std::unique_ptr<Patterns::PatternBase>
    range_pattern(const OverridableEntry &entry)
    {
      if (entry.integer)
        return std::make_unique<Patterns::Integer>(int(entry.low),
                                                   int(entry.high));
      return std::make_unique<Patterns::Double>(entry.low, entry.high);
    }


    void
    declare_overrides(ParameterHandler                    &prm,
                      const std::string                   &subsection,
                      const std::vector<OverridableEntry> &entries)
    {
      prm.enter_subsection(subsection);
      for (const OverridableEntry &entry : entries)
        prm.declare_entry(entry.name,
                          "",
                          Patterns::Anything(),
                          "Empty: as " + subsection + "/" + entry.name
                            + "; otherwise this stage's value. "
                            + entry.description);
      prm.leave_subsection();
    }


    void
    parse_overrides(
      ParameterHandler                    &prm,
      const std::string                   &subsection,
      const std::vector<OverridableEntry> &entries,
      const std::string                   &prefix,
      const std::function<void(const std::string &, const std::string &)> &set)
    {
      prm.enter_subsection(subsection);
      for (const OverridableEntry &entry : entries)
      {
        const std::string value = Utilities::trim(prm.get(entry.name));
        if (value.empty())
          continue;
        const auto allowed = range_pattern(entry);
        if (!allowed->match(value))
        {
          prm.leave_subsection();
          throw InputError(prefix + subsection + "/" + entry.name + " = '"
                           + io::one_line(value) + "': allowed are "
                           + allowed->description() + ", or empty");
        }
        set(entry.name, value);
      }
      prm.leave_subsection();
    }


    std::string
    first_override(ParameterHandler                    &prm,
                   const std::string                   &subsection,
                   const std::vector<OverridableEntry> &entries)
    {
      prm.enter_subsection(subsection);
      std::string name;
      for (const OverridableEntry &entry : entries)
        if (name.empty() && !Utilities::trim(prm.get(entry.name)).empty())
          name = entry.name;
      prm.leave_subsection();
      return name;
    }
  } // namespace solver
} // namespace deepdraw
