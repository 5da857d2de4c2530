#include <cerrno>
#include <cstdio>
#include <cstring>
#include <deepdraw/io/child_process.h>
#include <deepdraw/io/gnuplot.h>
#include <deepdraw/io/output_file.h>
#include <deepdraw/io/writing_rank.h>

namespace deepdraw
{
  namespace io
  {
    std::string
    gnuplot_string(const std::string &text)
    {
      std::string result;
      for (const char c : text)
        result += c == '\'' ? "''" : std::string(1, c);
      return "'" + result + "'";
    }


    std::string
    plot_with_gnuplot(const std::string &directory,
                      const std::string &name,
                      const std::string &script)
    {
      if (!writes_files())
        return "";
      write_file_atomically(directory + "/" + name + ".gp", script);
      const std::string log   = directory + "/" + name + "_gnuplot.log";
      int               error = 0;
      const int         code
        = run_program("gnuplot", {name + ".gp"}, directory, log, &error);
      if (code == 0)
      {
        std::remove(log.c_str());
        return name + ".png written";
      }
      if (error == ENOENT)
        return "gnuplot not found, " + name
               + ".png not written (install gnuplot, then run 'gnuplot " + name
               + ".gp' in " + directory + ")";
      if (error != 0)
        return std::string("cannot start gnuplot: ") + std::strerror(error);
      return "gnuplot failed, " + name + ".png not written (see " + log + ")";
    }
  } // namespace io
} // namespace deepdraw
