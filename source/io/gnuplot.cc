// gnuplot as a child process (doc/decisions.md D43).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <deepdraw/io/gnuplot.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

extern char **environ;

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
    run_gnuplot(const std::string &directory,
                const std::string &script,
                const std::string &png)
    {
      const std::string log = script + ".log";
      const std::string later
        = "; run 'gnuplot " + script + "' in " + directory + " to make it";
      // The log is opened after the chdir, so that it lies in directory.
      posix_spawn_file_actions_t actions;
      posix_spawn_file_actions_init(&actions);
      posix_spawn_file_actions_addchdir_np(&actions, directory.c_str());
      posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
      posix_spawn_file_actions_addopen(&actions,
                                       1,
                                       log.c_str(),
                                       O_WRONLY | O_CREAT | O_TRUNC,
                                       0644);
      posix_spawn_file_actions_adddup2(&actions, 1, 2);
      char     *argv[] = {const_cast<char *>("gnuplot"),
                          const_cast<char *>(script.c_str()),
                          nullptr};
      pid_t     pid    = 0;
      const int start
        = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
      posix_spawn_file_actions_destroy(&actions);
      if (start == ENOENT)
        return "gnuplot not found, " + png + " not written (install gnuplot"
               + later + ")";
      if (start != 0)
        return "cannot start gnuplot (" + std::string(std::strerror(start))
               + "), " + png + " not written" + later;
      int   status = 0;
      pid_t waited = 0;
      do
        waited = waitpid(pid, &status, 0);
      while (waited < 0 && errno == EINTR);
      if (waited == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0)
      {
        std::remove((directory + "/" + log).c_str());
        return png + " written";
      }
      return "gnuplot failed, " + png + " not written (see " + directory + "/"
             + log + ")";
    }
  } // namespace io
} // namespace deepdraw
