#include <chrono>
#include <cstdio>
#include <deepdraw/parallel/ranks.h>
#include <deepdraw/parallel/run_agreement.h>
#include <fcntl.h>
#include <mpi.h>
#include <string>
#include <thread>
#include <unistd.h>

namespace deepdraw
{
  namespace parallel
  {
    namespace
    {
      // The agreements have a communicator of their own: a rank that ends
      // early must not meet a collective operation of the run.
      MPI_Comm agreement = MPI_COMM_NULL;
      // The start is over, or an agreement failed.
      bool settled = false;
      // Ranks > 0: their own standard error (the terminal), and the file
      // that takes what the run prints there.
      int   terminal_error = -1;
      FILE *kept_error     = nullptr;

      // The last line this rank printed to its standard error.
      std::string
      last_kept_line()
      {
        if (kept_error == nullptr)
          return "";
        std::fflush(stderr);
        std::string text;
        char        buffer[4096];
        std::rewind(kept_error);
        while (std::size_t n = std::fread(buffer, 1, sizeof buffer, kept_error))
          text.append(buffer, n);
        while (!text.empty() && text.back() == '\n')
          text.pop_back();
        return text.substr(text.find_last_of('\n') + 1);
      }
    } // namespace


    RankFailure::RankFailure(const int code)
        : code(code)
    {
    }


    const char *
    RankFailure::what() const noexcept
    {
      return "another MPI rank could not start the run";
    }


    void
    start_ranks()
    {
      if (n_ranks() == 1)
        return;
      MPI_Comm_dup(MPI_COMM_WORLD, &agreement);
      // Collective: counted here, where every rank is, for the memory
      // check (D209).
      ranks_on_this_machine();
      if (is_root())
        return;
      std::fflush(stdout);
      std::fflush(stderr);
      const int null = ::open("/dev/null", O_WRONLY);
      if (null >= 0)
      {
        ::dup2(null, STDOUT_FILENO);
        ::close(null);
      }
      terminal_error = ::dup(STDERR_FILENO);
      kept_error     = std::tmpfile();
      if (kept_error != nullptr)
        ::dup2(fileno(kept_error), STDERR_FILENO);
    }


    void
    agree_on_start(const int code)
    {
      if (settled || agreement == MPI_COMM_NULL)
        return;
      int result = code;
      MPI_Allreduce(&code, &result, 1, MPI_INT, MPI_MAX, agreement);
      if (result == 0)
        return;
      settled = true;
      if (code == 0)
        throw RankFailure(result);
    }


    void
    start_agreed()
    {
      settled = true;
    }


    int
    end_run(const int code, const double patience)
    {
      if (agreement == MPI_COMM_NULL)
        return code;
      if (!settled)
        try
        {
          agree_on_start(code);
        }
        catch (const RankFailure &failure)
        {
          return failure.code;
        }
      int         result = code;
      MPI_Request request;
      MPI_Iallreduce(&code, &result, 1, MPI_INT, MPI_MAX, agreement, &request);
      const auto start = std::chrono::steady_clock::now();
      for (int done = 0;;)
      {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done)
          return result;
        const std::chrono::duration<double> waited
          = std::chrono::steady_clock::now() - start;
        if (code != 0 && waited.count() > patience)
          break;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      // This rank stopped and another is still in the run.
      if (!is_root() && terminal_error >= 0)
      {
        const std::string line = "deepdraw: MPI rank "
                                 + std::to_string(this_rank()) + ": "
                                 + last_kept_line() + "\n";
        [[maybe_unused]] const auto written
          = ::write(terminal_error, line.data(), line.size());
      }
      MPI_Abort(MPI_COMM_WORLD, code);
      return code;
    }
  } // namespace parallel
} // namespace deepdraw
