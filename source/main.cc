// deepdraw: implicit simulation of sheet-metal deep drawing. main() starts
// MPI (one rank without mpirun, app/single_process_mpi.h; N ranks under
// mpirun, parallel/run_agreement.h) and the signal set-up and hands
// the command line to app::run_command_line (app/command_line.h, exit codes
// in doc/user_guide.md §1 and §5).
#include <csignal>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deepdraw/app/blas_kernels.h>
#include <deepdraw/app/command_line.h>
#include <deepdraw/app/single_process_mpi.h>
#include <deepdraw/io/writing_rank.h>
#include <deepdraw/parallel/ranks.h>
#include <deepdraw/parallel/run_agreement.h>
#include <iostream>
#include <string>
#include <vector>

int
main(int argc, char *argv[])
{
  // Before anything else: it may start the program again (D210).
  deepdraw::app::choose_blas_kernels(argv);
  if (const std::string problem = deepdraw::app::working_directory_problem();
      !problem.empty())
  {
    std::cerr << "deepdraw: error in the input: " << problem << std::endl;
    return 2;
  }
  const deepdraw::app::SingleProcessMpi single_process_mpi;
  // As many threads as cores, shared among the ranks on one machine (or
  // DEAL_II_NUM_THREADS): the element
  // assembly runs in a WorkStream loop whose copier adds the cells in a
  // fixed order, so the results do not depend on the thread count (D61).
  dealii::Utilities::MPI::MPI_InitFinalize
    mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  // Under mpirun every rank runs the model; rank 0 alone prints and writes
  // (D199).
  deepdraw::parallel::start_ranks();
  deepdraw::io::set_writes_files(deepdraw::parallel::is_root());
  dealii::deal_II_exceptions::disable_abort_on_exception();
  // With a file size limit (ulimit -f) a write beyond it raises SIGXFSZ,
  // which kills the process; ignored, the write fails with EFBIG and is
  // reported like a full disk (exit code 3, D51).
  std::signal(SIGXFSZ, SIG_IGN);
  const int code = deepdraw::app::run_command_line(
    std::vector<std::string>(argv + 1, argv + argc));
  return deepdraw::parallel::end_run(code);
}
