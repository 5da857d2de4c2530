// How the ranks of a run start and end together (doc/user_guide.md §1.3,
// D199). Every rank reads and checks the input itself, and all take the
// same decisions, so an input error ends every rank with the same code.
// What only rank 0 does (the output directory, its lock, the files) can
// fail on rank 0 alone: the ranks agree after each such step of the start,
// before the next operation that needs all of them, and again at the end,
// so that none waits for ever for another.
#ifndef deepdraw_parallel_run_agreement_h
#define deepdraw_parallel_run_agreement_h

#include <exception>
#include <string>

namespace deepdraw
{
  namespace parallel
  {
    // Another rank could not start the run (rank 0 printed why): this rank
    // ends with its exit code.
    class RankFailure : public std::exception
    {
    public:
      explicit RankFailure(int code);
      const char     *
      what() const noexcept override;
      int code;
    };

    // Called by every rank right after MPI starts. Ranks other than 0
    // print nothing (their standard output is discarded and their
    // standard error kept aside for end_run) and write no files (main sets
    // io::set_writes_files).
    void
    start_ranks();

    // Every rank of a run calls this at the same points of its start,
    // after each step that rank 0 does alone, with code 0; a rank that
    // stopped before one of them calls it from end_run with its exit code.
    // Throws RankFailure on a rank that was ready when another was not.
    // Between two such points there must be no operation that needs all
    // ranks (an assembly, a factorisation).
    void
    agree_on_start(int code = 0);
    // The start is over: the ranks agree no more until end_run.
    void
    start_agreed();

    // The run's exit code: the largest of the ranks' codes. A rank that
    // ends with a nonzero code waits `patience` seconds for the others;
    // if one is still busy in the run (a failure of this rank alone, such
    // as a full disk on rank 0), it prints the reason and ends the whole
    // job with MPI_Abort and its code, so that no rank hangs.
    int
    end_run(int code, double patience = 60.);
  } // namespace parallel
} // namespace deepdraw

#endif
