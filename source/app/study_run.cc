// A run of a study as a child process (doc/decisions.md D42).
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <deepdraw/app/single_process_mpi.h>
#include <deepdraw/app/study_run.h>
#include <deepdraw/io/child_process.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/state/stop_request.h>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <vector>

namespace deepdraw
{
  namespace app
  {
    namespace
    {
      // An executable file at this path, or (a name without a slash) in
      // one of the folders of PATH.
      bool
      is_program(const std::string &name)
      {
        if (name.find('/') != std::string::npos)
          return ::access(name.c_str(), X_OK) == 0;
        const char        *path = std::getenv("PATH");
        std::istringstream folders(path != nullptr ? path : "");
        for (std::string folder; std::getline(folders, folder, ':');)
          if (::access(((folder.empty() ? "." : folder) + "/" + name).c_str(),
                       X_OK)
              == 0)
            return true;
        return false;
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


    std::vector<std::string>
    study_launcher()
    {
      const char              *setting = std::getenv("DEEPDRAW_MPI_LAUNCHER");
      std::vector<std::string> words;
      std::istringstream       text(setting != nullptr ? setting : "");
      for (std::string word; text >> word;)
        words.push_back(word);
      if (words.empty())
        return words;
      if (!is_program(words[0]))
        throw InputError("DEEPDRAW_MPI_LAUNCHER = '" + io::one_line(setting)
                         + "': the program '" + io::one_line(words[0])
                         + "' is not found (allowed: mpirun and its options, "
                           "such as 'mpirun -np 4')");
      restore_mpi_environment();
      return words;
    }


    StudyRunOutcome
    run_deepdraw(const std::string              &executable,
                 const std::string              &input_prm,
                 const std::string              &run_directory,
                 const std::vector<std::string> &launcher)
    {
      const io::Redirections   redirections{"",
                                          run_directory + "/deepdraw.log",
                                          run_directory + "/deepdraw.err"};
      int                      error = 0, signal = 0;
      StudyRunOutcome          outcome;
      const auto               start     = std::chrono::steady_clock::now();
      std::vector<std::string> arguments = launcher;
      arguments.insert(arguments.end(),
                       {launcher.empty() ? "deepdraw" : executable,
                        input_prm,
                        "--output-directory",
                        run_directory});
      outcome.exit_code
        = io::spawn_and_wait(launcher.empty() ? executable : launcher[0],
                             !launcher.empty(),
                             arguments,
                             redirections,
                             &error,
                             &signal,
                             &state::requested_stop_signal);
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
  } // namespace app
} // namespace deepdraw
