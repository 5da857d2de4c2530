#include <cstdio>
#include <deepdraw/blank/gmsh_file_check.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/regular_file.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace deepdraw
{
  namespace blank
  {
    namespace
    {
      std::vector<std::string>
      split_lines(const std::string &text)
      {
        std::vector<std::string> lines;
        std::istringstream       in(text);
        std::string              line;
        while (std::getline(in, line))
        {
          if (!line.empty() && line.back() == '\r')
            line.pop_back();
          lines.push_back(line);
        }
        return lines;
      }
    } // namespace


    std::string
    read_gmsh_text(const std::string &filename)
    {
      const std::string name = io::one_line(filename, 300);
      io::check_regular_file(filename, "mesh file");
      std::error_code error;
      if (std::filesystem::file_size(filename, error) > max_gmsh_file_size)
        throw InputError(name + ": more than the "
                         + std::to_string(max_gmsh_file_size >> 20)
                         + " MB a mesh file may have");
      std::ifstream     in(filename, std::ios::binary);
      const std::string text((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
      const auto fail = [&](const std::size_t line, const std::string &what)
      { throw InputError(name + ":" + std::to_string(line) + ": " + what); };

      const std::vector<std::string> lines = split_lines(text);
      for (std::size_t k = 0; k < lines.size(); ++k)
      {
        // Gmsh's binary format: "version 1 data-size" after $MeshFormat.
        if (lines[k] == "$MeshFormat" && k + 1 < lines.size())
        {
          double             version   = 0.;
          int                file_type = 0;
          std::istringstream header(lines[k + 1]);
          if ((header >> version >> file_type) && file_type == 1)
            fail(k + 2,
                 "a binary Gmsh file; deepdraw reads ASCII .msh files "
                 "(Gmsh: File > Export with 'Save all elements' and without "
                 "'Binary', or -format msh2)");
        }
        if ((lines[k] != "$Nodes" && lines[k] != "$Elements")
            || k + 1 >= lines.size())
          continue;
        // Format 2: "count"; format 4: "blocks count min-tag max-tag".
        std::istringstream counts(lines[k + 1]);
        unsigned long long first = 0, second = 0;
        if (!(counts >> first))
          continue; // GridIn reports the malformed section
        const unsigned long long announced
          = (counts >> second) ? second : first;
        const unsigned long long left = lines.size() - (k + 2);
        if (announced > left)
          fail(k + 2,
               "the " + lines[k].substr(1) + " section announces "
                 + std::to_string(announced) + " entries, but only "
                 + std::to_string(left)
                 + " lines follow (a damaged or cut-short mesh file)");
      }
      // GridIn's own messages quote lines; binary bytes must not reach
      // them (checked after the frame: a binary Gmsh file is named so).
      if (const std::size_t bad = io::find_non_text_byte(text);
          bad != std::string::npos)
      {
        std::size_t line = 1;
        for (std::size_t i = 0; i < bad; ++i)
          line += text[i] == '\n';
        char byte[8];
        std::snprintf(byte,
                      sizeof(byte),
                      "0x%02X",
                      unsigned(static_cast<unsigned char>(text[bad])));
        fail(line,
             std::string("not a text file (byte ") + byte
               + "); deepdraw reads ASCII Gmsh .msh files");
      }
      return text;
    }
  } // namespace blank
} // namespace deepdraw
