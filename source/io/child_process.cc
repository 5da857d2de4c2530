// Child processes (io/child_process.h): posix_spawn with redirections.
#include <cerrno>
#include <csignal>
#include <deepdraw/io/child_process.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

extern char **environ;

namespace deepdraw
{
  namespace io
  {
    int
    spawn_and_wait(const std::string              &program,
                   const bool                      search_path,
                   const std::vector<std::string> &arguments,
                   const Redirections             &redirections,
                   int                            *error,
                   int                            *signal,
                   int (*stop_signal)())
    {
      std::vector<char *> argv;
      for (const std::string &argument : arguments)
        argv.push_back(const_cast<char *>(argument.c_str()));
      argv.push_back(nullptr);

      posix_spawn_file_actions_t actions;
      posix_spawn_file_actions_init(&actions);
      const int write_flags = O_WRONLY | O_CREAT | O_TRUNC;
      posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
      posix_spawn_file_actions_addopen(&actions,
                                       1,
                                       redirections.stdout_file.c_str(),
                                       write_flags,
                                       0644);
      if (redirections.stderr_file == redirections.stdout_file)
        posix_spawn_file_actions_adddup2(&actions, 1, 2);
      else
        posix_spawn_file_actions_addopen(&actions,
                                         2,
                                         redirections.stderr_file.c_str(),
                                         write_flags,
                                         0644);
      if (!redirections.directory.empty())
        posix_spawn_file_actions_addchdir_np(&actions,
                                             redirections.directory.c_str());

      pid_t     pid    = 0;
      const int result = search_path ? posix_spawnp(&pid,
                                                    program.c_str(),
                                                    &actions,
                                                    nullptr,
                                                    argv.data(),
                                                    environ)
                                     : posix_spawn(&pid,
                                                   program.c_str(),
                                                   &actions,
                                                   nullptr,
                                                   argv.data(),
                                                   environ);
      posix_spawn_file_actions_destroy(&actions);
      if (result != 0)
      {
        *error = result;
        return -1;
      }
      int  status    = 0;
      bool forwarded = false;
      while (waitpid(pid, &status, 0) < 0)
      {
        if (errno != EINTR)
        {
          *error = errno;
          return -1;
        }
        if (stop_signal != nullptr && !forwarded && stop_signal() != 0)
        {
          ::kill(pid, stop_signal());
          forwarded = true;
        }
      }
      if (WIFEXITED(status))
        return WEXITSTATUS(status);
      *signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
      return -1;
    }


    int
    run_program(const std::string              &program,
                const std::vector<std::string> &arguments,
                const std::string              &directory,
                const std::string              &log_file,
                int                            *start_error)
    {
      std::vector<std::string> argv = {program};
      argv.insert(argv.end(), arguments.begin(), arguments.end());
      int       error = 0, signal = 0;
      const int code = spawn_and_wait(program,
                                      true,
                                      argv,
                                      {directory, log_file, log_file},
                                      &error,
                                      &signal);
      if (start_error != nullptr)
        *start_error = error;
      return code;
    }
  } // namespace io
} // namespace deepdraw
