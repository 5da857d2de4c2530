#include <deal.II/base/utilities.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/parameter_file.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/text_file.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace deepdraw
{
  namespace io
  {
    namespace
    {
      // Where an include was met: the including file and its line.
      struct IncludeSite
      {
        std::string file;
        std::string canonical;
        unsigned    line = 0;
      };

      std::string
      describe_chain(const std::vector<IncludeSite> &chain)
      {
        std::string text;
        for (const IncludeSite &site : chain)
          text += (text.empty() ? "" : ", ") + one_line(site.file, 300) + ":"
                  + std::to_string(site.line);
        return text;
      }

      bool
      starts_with(const std::string &text, const char *prefix)
      {
        return text.rfind(prefix, 0) == 0;
      }

      // The logical lines of a prm text as deal.II's ParameterHandler sees
      // them (parse_input and scan_line, deal.II 9.4): each line trimmed, a
      // trailing '\' joins the next line, then the comment from '#' on is
      // removed, tabs become spaces, and the result is trimmed again.
      // Returns (first physical line number, logical line) pairs.
      std::vector<std::pair<unsigned, std::string>>
      logical_lines(const std::string &text)
      {
        std::vector<std::pair<unsigned, std::string>> lines;
        std::istringstream                            input(text);
        std::string                                   line, joined;
        unsigned int                                  number = 0, first = 0;
        bool                                          continued = false;
        const auto                                    finish    = [&]()
        {
          std::string logical = joined;
          if (logical.find('#') != std::string::npos)
            logical.erase(logical.find('#'));
          for (char &c : logical)
            if (c == '\t')
              c = ' ';
          logical = dealii::Utilities::trim(logical);
          if (!logical.empty())
            lines.emplace_back(first, logical);
          joined.clear();
        };
        while (std::getline(input, line))
        {
          ++number;
          if (!continued)
            first = number;
          line = dealii::Utilities::trim(line);
          if (!line.empty() && line.back() == '\\')
          {
            line.pop_back();
            joined += line;
            continued = true;
            continue;
          }
          joined += line;
          continued = false;
          finish();
        }
        if (continued)
          finish();
        return lines;
      }

      bool
      starts_with_byte_order_mark(const std::string &filename)
      {
        std::ifstream file(filename, std::ios::binary);
        char          head[3] = {0, 0, 0};
        file.read(head, 3);
        return file.gcount() == 3 && std::string(head, 3) == "\xEF\xBB\xBF";
      }

      // Includes followed in all (a file may include another one many
      // times, and that one again: the count grows exponentially with the
      // depth).
      constexpr unsigned int max_includes = 1000;

      void
      scan_file(const std::string        &filename,
                std::vector<IncludeSite> &chain,
                unsigned int             &n_includes)
      {
        std::string text;
        try
        {
          text = read_text_file(filename, "parameter file");
        }
        catch (const InputError &error)
        {
          if (chain.empty())
            throw;
          throw InputError(std::string(error.what()) + " (included from "
                           + describe_chain(chain) + ")");
        }
        // deal.II reads an included file itself, without dropping a
        // byte-order mark as read_text_file does for the top-level one.
        if (!chain.empty() && starts_with_byte_order_mark(filename))
          throw InputError(one_line(filename, 300)
                           + ": begins with a UTF-8 byte-order mark, which "
                             "an included parameter file may not have (save "
                             "it as UTF-8 without one; included from "
                           + describe_chain(chain) + ")");
        std::error_code   ignored;
        const std::string canonical
          = std::filesystem::weakly_canonical(filename, ignored).string();

        for (const auto &[number, line] : logical_lines(text))
        {
          const std::string where
            = one_line(filename, 300) + ":" + std::to_string(number) + ": ";
          if (starts_with(line, "set ") || starts_with(line, "SET "))
          {
            const auto equal = line.find('=');
            if (equal != std::string::npos
                && line.find('{', equal) != std::string::npos)
              throw InputError(where
                               + "a value with '{' (deal.II's syntax for "
                                 "several runs) is not supported by "
                                 "deepdraw");
          }
          if (!starts_with(line, "include ") && !starts_with(line, "INCLUDE "))
            continue;
          std::string included = line.substr(7);
          while (!included.empty() && included[0] == ' ')
            included.erase(0, 1);
          if (included.empty())
            continue; // deal.II reports an include without a file name
          chain.push_back({filename, canonical, number});
          const std::string target
            = std::filesystem::weakly_canonical(included, ignored).string();
          for (const IncludeSite &site : chain)
            if (site.canonical == target)
              throw InputError(where + "'" + one_line(line, 300)
                               + "' makes an include cycle: "
                               + describe_chain(chain) + " includes "
                               + one_line(included, 300) + " again");
          if (chain.size() > max_include_depth)
            throw InputError(where + "includes nested more than "
                             + std::to_string(max_include_depth)
                             + " deep: " + describe_chain(chain));
          if (++n_includes > max_includes)
            throw InputError(where + "more than " + std::to_string(max_includes)
                             + " include lines followed in all");
          scan_file(included, chain, n_includes);
          chain.pop_back();
        }
      }

      bool
      ends_with(const std::string &text, const std::string &suffix)
      {
        return text.size() >= suffix.size()
               && text.compare(text.size() - suffix.size(),
                               suffix.size(),
                               suffix)
                    == 0;
      }
    } // namespace


    void
    read_parameter_file(dealii::ParameterHandler &prm,
                        const std::string        &filename)
    {
      const bool xml  = ends_with(filename, ".xml"),
                 json = ends_with(filename, ".json");
      if (!xml && !json && !ends_with(filename, ".prm"))
      {
        // deal.II's ParameterHandler decides the format by the ending; it
        // is checked after the file itself, which gives the better message
        // for a directory or a missing file.
        read_text_file(filename, "parameter file");
        throw InputError(one_line(filename, 300)
                         + ": a parameter file must end in .prm (or .xml, "
                           ".json for deal.II's other formats)");
      }
      std::string text;
      if (xml || json)
        text = read_text_file(filename, "parameter file");
      else
      {
        std::vector<IncludeSite> chain;
        unsigned int             n_includes = 0;
        scan_file(filename, chain, n_includes);
        text = read_text_file(filename, "parameter file");
      }
      try
      {
        std::istringstream input(text);
        if (xml)
          prm.parse_input_from_xml(input);
        else if (json)
          prm.parse_input_from_json(input);
        else
          prm.parse_input(input, filename);
      }
      catch (const dealii::ExceptionBase &error)
      {
        throw InputError(deal_ii_message(error));
      }
      catch (const InputError &)
      {
        throw;
      }
      catch (const std::exception &error)
      {
        // boost's XML and JSON readers throw their own types.
        throw InputError(one_line(filename, 300) + ": "
                         + one_line(error.what()));
      }
    }
  } // namespace io
} // namespace deepdraw
