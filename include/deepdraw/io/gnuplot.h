// A PNG drawn by gnuplot from a script written next to it (D43: the plots
// of deepdraw are gnuplot scripts, so that a user can rerun and adapt them;
// study.png, section_profile.png, flc.png, fld_*.png). gnuplot is optional:
// its absence or failure is reported, never an error of the run.
#ifndef deepdraw_io_gnuplot_h
#define deepdraw_io_gnuplot_h

#include <string>

namespace deepdraw
{
  namespace io
  {
    // text as a gnuplot string in single quotes (a quote inside doubled).
    std::string
    gnuplot_string(const std::string &text);

    // Writes directory/name.gp (the script, which writes name.png; an
    // OutputError if it cannot be written) and runs gnuplot on it there.
    // Returns "name.png written", or why not (gnuplot missing or failed: its
    // log is kept in name_gnuplot.log, the script stays for a later run).
    std::string
    plot_with_gnuplot(const std::string &directory,
                      const std::string &name,
                      const std::string &script);
  } // namespace io
} // namespace deepdraw

#endif
