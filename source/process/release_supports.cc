#include <cmath>
#include <deal.II/base/utilities.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/process/release_supports.h>

namespace deepdraw
{
  namespace process
  {
    namespace
    {
      const char *const syntax
        = "expected 'point(X, Y, Z): COMPONENTS' with X, Y, Z numbers (mm) "
          "and COMPONENTS one or more of ux, uy, uz, items separated by ';'";

      // The coordinates between "point(" and ")".
      Point<3>
      parse_point(const std::string &text, const std::string &where)
      {
        const std::vector<std::string> numbers
          = Utilities::split_string_list(text, ',');
        if (numbers.size() != 3)
          throw InputError(where);
        Point<3> point;
        for (unsigned int d = 0; d < 3; ++d)
        {
          try
          {
            point[d] = Utilities::string_to_double(numbers[d]);
          }
          catch (...)
          {
            throw InputError(where);
          }
          if (!std::isfinite(point[d]) || std::abs(point[d]) > 1e9)
            throw InputError(where);
        }
        return point;
      }
    } // namespace


    std::vector<ReleaseSupport>
    parse_release_supports(const std::string &text,
                           const std::string &parameter)
    {
      std::vector<ReleaseSupport> supports;
      for (const std::string &item : Utilities::split_string_list(text, ';'))
      {
        if (item.empty())
          continue;
        const std::string where
          = parameter + ": cannot read '" + io::one_line(item) + "'; " + syntax;
        const auto open  = item.find('(');
        const auto close = item.find(')');
        const auto colon
          = item.find(':', close == std::string::npos ? 0 : close);
        if (Utilities::trim(item.substr(0, open)) != "point"
            || open == std::string::npos || close == std::string::npos
            || close < open || colon == std::string::npos)
          throw InputError(where);
        ReleaseSupport support;
        support.item = item;
        support.point
          = parse_point(item.substr(open + 1, close - open - 1), where);
        if (!Utilities::trim(item.substr(close + 1, colon - close - 1)).empty())
          throw InputError(where);
        const std::vector<std::string> names
          = Utilities::split_string_list(item.substr(colon + 1), ' ');
        for (const std::string &name : names)
        {
          if (name.empty())
            continue;
          const unsigned int c = name == "ux"   ? 0
                                 : name == "uy" ? 1
                                 : name == "uz" ? 2
                                                : 3;
          if (c == 3 || support.components[c])
            throw InputError(parameter + ": '" + io::one_line(name) + "' in '"
                             + io::one_line(item)
                             + "': allowed are ux, uy, uz, each once");
          support.components[c] = true;
        }
        if (!support.components[0] && !support.components[1]
            && !support.components[2])
          throw InputError(where);
        supports.push_back(support);
      }
      return supports;
    }


    std::string
    component_names(const std::array<bool, 3> &components)
    {
      std::string names;
      for (unsigned int c = 0; c < 3; ++c)
        if (components[c])
          names += (names.empty() ? "u" : " u") + std::string(1, "xyz"[c]);
      return names;
    }
  } // namespace process
} // namespace deepdraw
