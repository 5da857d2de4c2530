// A PNG from a gnuplot script written beside it (doc/decisions.md D43: the
// plots of deepdraw are gnuplot scripts, so that a user can rerun and
// adapt them). gnuplot is optional: its absence or failure is reported,
// never an error of the run.
#ifndef deepdraw_io_gnuplot_h
#define deepdraw_io_gnuplot_h

#include <string>

namespace deepdraw
{
  namespace io
  {
    // Runs `gnuplot script` (searched in PATH) in directory, stdin from
    // /dev/null, stdout and stderr to directory/<script>.log (removed when
    // gnuplot succeeds), and waits for it. Returns one line for the
    // console: "<png> written", or why not (gnuplot not found, failed, or
    // could not be started), with how to make the picture later.
    // text as a gnuplot string in single quotes (a quote inside doubled).
    std::string
    gnuplot_string(const std::string &text);

    std::string
    run_gnuplot(const std::string &directory,
                const std::string &script,
                const std::string &png);
  } // namespace io
} // namespace deepdraw

#endif
