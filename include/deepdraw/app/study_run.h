// One run of a refinement study (doc/user_guide.md §4.2, doc/decisions.md
// D42): the same executable started as a child process on the run's
// input.prm, its console output kept in the run folder, its exit code and
// its last message on stderr as the reason of a failure, and the wall time
// measured around it.
#ifndef deepdraw_app_study_run_h
#define deepdraw_app_study_run_h

#include <string>
#include <vector>

namespace deepdraw
{
  namespace app
  {
    struct StudyRunOutcome
    {
      // The child's exit code (doc/user_guide.md §1), or -1 if it could not
      // be started or was killed by a signal.
      int exit_code = -1;
      // Empty when it exited with 0; else its last message on stderr (from
      // the last line that starts with "deepdraw:", joined on one line), or
      // the exit code or signal if it wrote none.
      std::string failure;
      // From the start of the child to its end, s.
      double wall_seconds = 0.;
    };

    // Runs `executable input_prm --output-directory run_directory` in the
    // current directory (include paths of prm files are relative to it),
    // after the words of `launcher` (mpirun and its options; none: the
    // executable alone), stdout to run_directory/deepdraw.log, stderr to
    // deepdraw.err, stdin from /dev/null, and waits for it. run_directory
    // must exist.
    StudyRunOutcome
    run_deepdraw(const std::string              &executable,
                 const std::string              &input_prm,
                 const std::string              &run_directory,
                 const std::vector<std::string> &launcher = {});

    // The launcher of a study's runs: the words of the environment
    // variable DEEPDRAW_MPI_LAUNCHER ("mpirun -np 4"; unset or blank: none,
    // D200). Throws InputError if its program is not found in PATH. With a
    // launcher, Open MPI's variables of this process's environment, which
    // the runs inherit, are put back to what they were before MPI started
    // (restore_mpi_environment).
    std::vector<std::string>
    study_launcher();
  } // namespace app
} // namespace deepdraw

#endif
