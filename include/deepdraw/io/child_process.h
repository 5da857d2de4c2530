// Child processes: a program started with its output redirected and waited
// for (the runs of a study, D42; gnuplot, io/gnuplot.h).
#ifndef deepdraw_io_child_process_h
#define deepdraw_io_child_process_h

#include <string>
#include <vector>

namespace deepdraw
{
  namespace io
  {
    struct Redirections
    {
      std::string directory; // empty: the current one
      std::string stdout_file;
      std::string stderr_file;
    };

    // Starts program with arguments (argv[0] included; search_path: in
    // PATH) and waits for it; stdin from /dev/null. The exit code, or -1
    // (killed: *signal set; not started: *error). If the wait is
    // interrupted and stop_signal() is not 0, that signal is passed on to
    // the child (once), which then ends as it does on it (D179).
    int
    spawn_and_wait(const std::string              &program,
                   bool                            search_path,
                   const std::vector<std::string> &arguments,
                   const Redirections             &redirections,
                   int                            *error,
                   int                            *signal,
                   int (*stop_signal)() = nullptr);

    // Runs program (searched in PATH) with arguments in directory, its
    // output to log_file; returns its exit code, or -1 if it could not be
    // started (errno in *start_error) or was killed.
    int
    run_program(const std::string              &program,
                const std::vector<std::string> &arguments,
                const std::string              &directory,
                const std::string              &log_file,
                int                            *start_error = nullptr);
  } // namespace io
} // namespace deepdraw

#endif
