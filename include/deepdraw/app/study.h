// A refinement study in one command (doc/user_guide.md §4.2,
// doc/decisions.md D41-D44):
//   deepdraw FILE.prm --study "Subsection/Parameter = v1, v2, ..." [...]
// runs FILE.prm once per value, each run in its own folder of the output
// directory, and writes study.csv (one row per run) and study.png there.
#ifndef deepdraw_app_study_h
#define deepdraw_app_study_h

#include <string>
#include <vector>

namespace deepdraw
{
  namespace app
  {
    // Runs the study and returns deepdraw's exit code: 0 every run done,
    // 2 bad input (the prm or an option; nothing written), 3 a run failed
    // (its row says why; every other row is there) or the study could not
    // go on. output_directory: --output-directory, or empty for the prm's
    // Output/Output directory.
    int
    run_study(const std::string              &prm_file,
              const std::string              &output_directory,
              const std::vector<std::string> &options);
  } // namespace app
} // namespace deepdraw

#endif
