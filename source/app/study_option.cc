// The --study option (doc/user_guide.md §4.2, doc/decisions.md D41).
#include <deal.II/base/utilities.h>
#include <deepdraw/app/study_option.h>
#include <deepdraw/io/input_error.h>
#include <set>

namespace deepdraw
{
  namespace app
  {
    namespace
    {
      // The parts of text between the separators, trimmed.
      std::vector<std::string>
      split_trimmed(const std::string &text, const char separator)
      {
        std::vector<std::string> parts;
        std::string::size_type   start = 0;
        while (true)
        {
          const auto end = text.find(separator, start);
          parts.push_back(Utilities::trim(text.substr(start, end - start)));
          if (end == std::string::npos)
            return parts;
          start = end + 1;
        }
      }
    } // namespace


    std::string
    StudyVariable::name() const
    {
      std::string text;
      for (const std::string &subsection : subsections)
        text += subsection + "/";
      return text + entry;
    }


    StudyVariable
    parse_study_option(const std::string &text)
    {
      const std::string where = "--study \"" + text + "\": ";
      const auto        equal = text.find('=');
      if (equal == std::string::npos)
        throw InputError(where
                         + "expected 'Subsection/Parameter = value, value, "
                           "...'");
      std::vector<std::string> path = split_trimmed(text.substr(0, equal), '/');
      for (const std::string &part : path)
        if (part.empty())
          throw InputError(where + "the parameter '"
                           + Utilities::trim(text.substr(0, equal))
                           + "' is not of the form Subsection/Parameter");
      StudyVariable variable;
      variable.entry = path.back();
      path.pop_back();
      variable.subsections = path;

      const std::string list = Utilities::trim(text.substr(equal + 1));
      if (list.empty())
        throw InputError(where + "no values for " + variable.name());
      variable.values = split_trimmed(list, ',');
      for (unsigned int k = 0; k < variable.values.size(); ++k)
        if (variable.values[k].empty())
          throw InputError(where + "value " + std::to_string(k + 1) + " of "
                           + variable.name() + " is empty");
      return variable;
    }


    bool
    is_declared(ParameterHandler               &prm,
                const std::vector<std::string> &subsections,
                const std::string              &entry)
    {
      for (const std::string &subsection : subsections)
        prm.enter_subsection(subsection);
      // get() of an undeclared entry returns "" in a release build; set()
      // throws. Setting the current value, which matches its pattern, is
      // no change.
      bool declared = true;
      try
      {
        prm.set(entry, prm.get(entry));
      }
      catch (const std::exception &)
      {
        declared = false;
      }
      for (unsigned int k = 0; k < subsections.size(); ++k)
        prm.leave_subsection();
      return declared;
    }


    void
    set_value(ParameterHandler    &prm,
              const StudyVariable &variable,
              const unsigned int   run)
    {
      for (const std::string &subsection : variable.subsections)
        prm.enter_subsection(subsection);
      try
      {
        prm.set(variable.entry, variable.values.at(run));
      }
      catch (...)
      {
        for (unsigned int k = 0; k < variable.subsections.size(); ++k)
          prm.leave_subsection();
        throw;
      }
      for (unsigned int k = 0; k < variable.subsections.size(); ++k)
        prm.leave_subsection();
    }


    std::vector<StudyVariable>
    parse_study_options(const std::vector<std::string> &texts,
                        ParameterHandler               &prm)
    {
      if (texts.empty())
        throw InputError("a study needs at least one --study option");
      std::vector<StudyVariable> variables;
      std::set<std::string>      names;
      for (const std::string &text : texts)
      {
        const StudyVariable variable = parse_study_option(text);
        const std::string   where    = "--study \"" + text + "\": ";
        if (!is_declared(prm, variable.subsections, variable.entry))
          throw InputError(where + variable.name()
                           + " is not a parameter (deepdraw "
                             "--print-parameters lists them)");
        if (variable.name() == "Output/Output directory")
          throw InputError(where
                           + "the study sets the output directory of each "
                             "run (use --output-directory for the study's)");
        if (!names.insert(variable.name()).second)
          throw InputError(where + variable.name()
                           + " is varied by two --study options");
        if (!variables.empty()
            && variable.values.size() != variables.front().values.size())
          throw InputError(
            where + std::to_string(variable.values.size()) + " values, but "
            + variables.front().name() + " has "
            + std::to_string(variables.front().values.size())
            + ": options that vary together need the same number");
        variables.push_back(variable);
      }
      return variables;
    }
  } // namespace app
} // namespace deepdraw
