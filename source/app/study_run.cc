// A run of a study as a child process (doc/decisions.md D42).
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <deepdraw/app/study_run.h>
#include <deepdraw/io/child_process.h>
#include <deepdraw/state/stop_request.h>
#include <fstream>
#include <sstream>
#include <vector>

namespace deepdraw
{
  namespace app
  {
    namespace
    {
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
      const io::Redirections redirections{"",
                                          run_directory + "/deepdraw.log",
                                          run_directory + "/deepdraw.err"};
      int                    error = 0, signal = 0;
      StudyRunOutcome        outcome;
      const auto             start = std::chrono::steady_clock::now();
      outcome.exit_code            = io::spawn_and_wait(
        executable,
        false,
        {"deepdraw", input_prm, "--output-directory", run_directory},
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
