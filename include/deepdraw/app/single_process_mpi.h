// Started without mpirun, deepdraw is one MPI process (under mpirun see
// parallel/run_agreement.h, D199).
// Started without a launcher (mpirun sets OMPI_COMM_WORLD_SIZE), Open MPI
// probes the network transports (UCX, OFI) for 0.2 s of every run; the
// in-process ones chosen here start at once (D98). Nor does it need the
// runtime daemon (0.1 s more): the daemon-less singleton runs with a session
// directory under a base of this process's own, since concurrent singletons
// under one base share a directory and fail (D98, D99). A setting the user
// made wins; a study's parent deepdraw passes its base on in the
// environment, which a child replaces by its own.
#ifndef deepdraw_app_single_process_mpi_h
#define deepdraw_app_single_process_mpi_h

#include <string>

namespace deepdraw
{
  namespace app
  {
    // Construct before MPI_Init (it sets Open MPI's environment), destroy
    // after MPI_Finalize (it removes the session base).
    class SingleProcessMpi
    {
    public:
      SingleProcessMpi();
      ~SingleProcessMpi();
      SingleProcessMpi(const SingleProcessMpi &) = delete;
      SingleProcessMpi &
      operator=(const SingleProcessMpi &)
        = delete;

    private:
      std::string session_base;
    };

    // Open MPI's variables (OMPI_, PMIX_, ORTE_, OPAL_) back to what they
    // were before the constructor and MPI_Init set theirs: a process started
    // under its own mpirun (a study's run, D200) would otherwise take this
    // singleton's settings for a job it runs in, and end at once.
    void
    restore_mpi_environment();

    // Open MPI's start-up aborts with pages of text when the working
    // directory has been deleted (D167): the reason, to be checked before
    // MPI_Init, or "" if getcwd(3) works.
    std::string
    working_directory_problem();
  } // namespace app
} // namespace deepdraw

#endif
