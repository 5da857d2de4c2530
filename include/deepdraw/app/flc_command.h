// deepdraw --flc FILE.prm (doc/user_guide.md §8): the forming-limit curve
// of the prm's subsection Formability, computed from its subsection
// Material where it is a Marciniak-Kuczynski curve, written as flc.csv and
// flc.png (app::flc_command reads the command line).
#ifndef deepdraw_app_flc_command_h
#define deepdraw_app_flc_command_h

#include <string>

namespace deepdraw
{
  namespace app
  {
    // Reads and checks prm_file like a run does (every subsection of the
    // program and Formability), then writes flc.csv, flc.gp and flc.png to
    // output_directory (created if missing; empty: Output/Output directory
    // of the prm). Returns the exit code: 0 written (a missing gnuplot only
    // leaves flc.png out, with a note), 2 bad input or an output directory
    // that cannot be created (nothing written), 3 a file that cannot be
    // written. Messages are one line on stderr starting with "deepdraw:".
    int
    run_flc_command(const std::string &prm_file,
                    const std::string &output_directory);
  } // namespace app
} // namespace deepdraw

#endif
