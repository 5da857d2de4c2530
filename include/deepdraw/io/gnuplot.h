// A PNG drawn by gnuplot from a script written next to it (study.png, D43;
// section_profile.png, D153).
#ifndef deepdraw_io_gnuplot_h
#define deepdraw_io_gnuplot_h

#include <string>

namespace deepdraw
{
  namespace io
  {
    // Writes directory/name.gp (the script, which writes name.png) and runs
    // gnuplot on it there. Returns "name.png written", or why not (gnuplot
    // missing or failed: its log is kept in name_gnuplot.log, the script
    // stays for a later run).
    std::string
    plot_with_gnuplot(const std::string &directory,
                      const std::string &name,
                      const std::string &script);
  } // namespace io
} // namespace deepdraw

#endif
