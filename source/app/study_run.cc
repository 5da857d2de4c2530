// A run of a study as a child process (doc/decisions.md D42).
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <deepdraw/app/study_run.h>
#include <fcntl.h>
#include <fstream>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <vector>

extern char **environ;

namespace deepdraw
{
  namespace app
  {
    namespace
    {
      struct Redirections
      {
        std::string directory; // empty: the current one
        std::string stdout_file;
        std::string stderr_file;
      };

      // Starts program with arguments (argv[0] included) and waits for it;
      // the exit code, or -1 (killed: *signal set; not started: *error).
      int
      spawn_and_wait(const std::string              &program,
                     const bool                      search_path,
                     const std::vector<std::string> &arguments,
                     const Redirections             &redirections,
                     int                            *error,
                     int                            *signal)
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
        int status = 0;
        while (waitpid(pid, &status, 0) < 0)
          if (errno != EINTR)
          {
            *error = errno;
            return -1;
          }
        if (WIFEXITED(status))
          return WEXITSTATUS(status);
        *signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
        return -1;
      }


      // What a run said last on stderr: from its last line that starts
      // with "deepdraw:" (its messages do, doc/user_guide.md §5) to the end,
      // on one line; else the last line that is not blank.
      std::string
      last_message(const std::string &filename)
      {
        std::ifstream            file(filename);
        std::vector<std::string> lines;
        std::string              line;
        unsigned int             start = 0;
        while (std::getline(file, line))
        {
          std::istringstream words(line);
          std::string        word, joined;
          while (words >> word)
            joined += (joined.empty() ? "" : " ") + word;
          if (joined.empty())
            continue;
          if (joined.rfind("deepdraw:", 0) == 0)
            start = lines.size();
          lines.push_back(joined);
        }
        if (lines.empty())
          return "";
        if (lines[start].rfind("deepdraw:", 0) != 0)
          start = lines.size() - 1;
        std::string message;
        for (unsigned int k = start; k < lines.size(); ++k)
          message += (message.empty() ? "" : " ") + lines[k];
        return message;
      }
    } // namespace


    StudyRunOutcome
    run_deepdraw(const std::string &executable,
                 const std::string &input_prm,
                 const std::string &run_directory)
    {
      const Redirections redirections{"",
                                      run_directory + "/deepdraw.log",
                                      run_directory + "/deepdraw.err"};
      int                error = 0, signal = 0;
      StudyRunOutcome    outcome;
      const auto         start = std::chrono::steady_clock::now();
      outcome.exit_code        = spawn_and_wait(
        executable,
        false,
        {"deepdraw", input_prm, "--output-directory", run_directory},
        redirections,
        &error,
        &signal);
      outcome.wall_seconds = std::chrono::duration<double>(
                               std::chrono::steady_clock::now() - start)
                               .count();
      if (outcome.exit_code == 0)
        return outcome;
      if (error != 0)
        outcome.failure
          = "could not start " + executable + ": " + std::strerror(error);
      else if (signal != 0)
        outcome.failure = "killed by signal " + std::to_string(signal) + " ("
                          + strsignal(signal) + ")";
      else
      {
        outcome.failure = last_message(redirections.stderr_file);
        if (outcome.failure.empty())
          outcome.failure = "exit code " + std::to_string(outcome.exit_code);
      }
      return outcome;
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
  } // namespace app
} // namespace deepdraw
