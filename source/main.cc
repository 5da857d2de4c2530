// deepdraw: implicit simulation of sheet-metal deep drawing.
//   deepdraw FILE.prm [--output-directory DIR]
//   deepdraw --check FILE.prm
//   deepdraw --help
//   deepdraw --print-parameters
// The program is problem::run_command_line (command_line.h); exit codes in
// doc/user_guide.md §1 and §5.
#include <csignal>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deepdraw/problem/command_line.h>
#include <string>
#include <vector>

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::deal_II_exceptions::disable_abort_on_exception();
  // With a file size limit (ulimit -f) a write beyond it raises SIGXFSZ,
  // which kills the process; ignored, the write fails with EFBIG and is
  // reported like a full disk (exit code 3, D51).
  std::signal(SIGXFSZ, SIG_IGN);
  return deepdraw::problem::run_command_line(
    std::vector<std::string>(argv + 1, argv + argc));
}
