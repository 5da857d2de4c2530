#include <array>
#include <deepdraw/geometry/cad_file_check.h>
#include <deepdraw/io/input_error.h>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

namespace deepdraw::geometry
{
  namespace
  {
    // The line of the first parenthesis nested deeper than
    // max_step_nesting, outside strings ('...', '' inside one) and
    // comments (/* ... */); 0 if there is none.
    unsigned int
    line_nested_too_deep(const std::string &text)
    {
      unsigned int depth = 0, line = 1;
      for (std::size_t i = 0; i < text.size(); ++i)
      {
        const char c = text[i];
        if (c == '\n')
          ++line;
        else if (c == '\'')
        {
          // To the closing apostrophe; '' is an apostrophe in the string.
          for (++i; i < text.size(); ++i)
            if (text[i] == '\n')
              ++line;
            else if (text[i] == '\'')
            {
              if (i + 1 < text.size() && text[i + 1] == '\'')
                ++i;
              else
                break;
            }
        }
        else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*')
        {
          const std::size_t end  = text.find("*/", i + 2);
          const std::size_t stop = end == std::string::npos ? text.size() : end;
          for (std::size_t k = i; k < stop; ++k)
            line += text[k] == '\n';
          i = end == std::string::npos ? text.size() : end + 1;
        }
        else if (c == '(' && ++depth > max_step_nesting)
          return line;
        else if (c == ')' && depth > 0)
          --depth;
      }
      return 0;
    }
  } // namespace


  void
  check_step_frame(const std::string &filename)
  {
    std::ifstream     in(filename, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)),
                           std::istreambuf_iterator<char>());
    const auto        first = text.find_first_not_of(" \t\r\n");
    const auto        last  = text.find_last_not_of(" \t\r\n");
    const std::string begin = "ISO-10303-21;", end = "END-ISO-10303-21;";
    if (first == std::string::npos
        || text.compare(first, begin.size(), begin) != 0)
      throw InputError(filename + ": not a STEP file (it does not begin with "
                       + begin + ")");
    if (last + 1 < end.size()
        || text.compare(last + 1 - end.size(), end.size(), end) != 0)
      throw InputError(filename
                       + ": the STEP file is incomplete (cut short?): it does "
                         "not end with "
                       + end);
    // OpenCASCADE's reader recurses once per level and overflows the stack
    // on some 10^5 levels (D165).
    if (const unsigned int line = line_nested_too_deep(text); line > 0)
      throw InputError(filename + ":" + std::to_string(line)
                       + ": parentheses nested more than "
                       + std::to_string(max_step_nesting)
                       + " deep; not a STEP file deepdraw reads (real "
                         "files nest fewer than 10)");
  }


  void
  check_iges_frame(const std::string &filename)
  {
    std::ifstream                in(filename, std::ios::binary);
    std::string                  line, last_line;
    std::map<char, unsigned int> counts;
    unsigned int                 number = 0, damaged_line = 0;
    while (std::getline(in, line))
    {
      ++number;
      if (!line.empty() && line.back() == '\r')
        line.pop_back();
      if (line.find_first_not_of(' ') == std::string::npos)
        continue;
      const char section = line.size() >= 73 ? line[72] : ' ';
      // The compressed ASCII form (C in column 73) has no fixed lines.
      if (number == 1 && section == 'C')
        return;
      if (damaged_line > 0 || section == '\0'
          || std::string("SGDPT").find(section) == std::string::npos)
      {
        // A line without its section letter: the last one of a file cut
        // short, or the file is no IGES file.
        if (damaged_line > 0 || number == 1)
          throw InputError(
            filename + ": not an IGES file (line "
            + std::to_string(damaged_line > 0 ? damaged_line : number)
            + " has no section letter S, G, D, P or T in "
              "column 73)");
        damaged_line = number;
        continue;
      }
      ++counts[section];
      last_line = line;
    }
    if (last_line.size() < 73 || last_line[72] != 'T')
      throw InputError(filename
                       + ": the IGES file is incomplete (cut short?): it does "
                         "not end with the terminate section (T)");
    // "S      1G      4D    242P    646": the line counts of S, G, D, P.
    const std::array<std::pair<char, const char *>, 4> sections
      = {{{'S', "start"},
          {'G', "global"},
          {'D', "directory"},
          {'P', "parameter"}}};
    for (unsigned int k = 0; k < 4; ++k)
    {
      const std::string field     = last_line.substr(8 * k, 8);
      unsigned int      announced = 0;
      std::istringstream(field.substr(1)) >> announced;
      if (field[0] != sections[k].first)
        throw InputError(filename
                         + ": the IGES file's terminate section is "
                           "damaged (\""
                         + last_line.substr(0, 32) + "\")");
      if (announced != counts[sections[k].first])
        throw InputError(filename
                         + ": the IGES file is incomplete (cut "
                           "short?): its terminate section announces "
                         + std::to_string(announced) + " " + sections[k].second
                         + " lines, the file has "
                         + std::to_string(counts[sections[k].first]));
    }
  }
} // namespace deepdraw::geometry
