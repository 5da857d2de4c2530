// The commands of deepdraw beside a run (app::run_command_line dispatches
// to them); arguments as given, the command's own first. Exit codes as in
// doc/user_guide.md §5.
#ifndef deepdraw_app_commands_h
#define deepdraw_app_commands_h

#include <string>
#include <vector>

namespace deepdraw
{
  namespace app
  {
    // --write-square-cup-tools DIR [FILE.prm]: the built-in tools as STEP
    // and IGES files (doc/tool_files.md, CAD tools), to check the CAD
    // reader against the exact builder or to start a CAD model from.
    int
    write_square_cup_tools(const std::vector<std::string> &arguments);

    // --flc FILE.prm [--output-directory DIR]: the forming-limit curve of
    // the prm's subsection Formability as flc.csv and flc.png
    // (app::run_flc_command).
    int
    flc_command(const std::vector<std::string> &arguments);

    // FILE.prm [--output-directory DIR] --study "..." [--study "..."]: a
    // refinement study (app::run_study).
    int
    run_study_command(const std::vector<std::string> &arguments);
  } // namespace app
} // namespace deepdraw

#endif
