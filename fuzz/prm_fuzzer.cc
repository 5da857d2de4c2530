// libFuzzer target: the prm reading path on arbitrary bytes, i.e. what
// deepdraw does before it writes anything: io::read_parameter_file (text
// checks, includes) and the FormingProblem constructor (every subsection
// parsed and checked, mesh, tools, pairs; doc/architecture.md). An input must
// either be accepted or rejected with deepdraw::InputError or a deal.II
// exception (both reported by main with exit code 2); any other exception
// (std::invalid_argument of a conversion, std::out_of_range, ...) is a check
// that is missing, and a sanitizer report is a bug: both abort. Built and
// run by scripts/fuzz.sh, not by ctest; run it in a directory with the
// links prm/ and data/ (the script makes them) so that seeds can include
// the shipped prm files and use the tests' tool files.
#include <cstdint>
#include <cstdlib>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/parameter_file.h>
#include <deepdraw/problem/forming_problem.h>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>
#include <unistd.h>

namespace
{
  // The harness sets up at most this many cells per input, to keep the
  // executions fast and within libFuzzer's memory limit; deepdraw's own
  // limit is the memory check (D53).
  constexpr double max_cells = 2000.;
} // namespace

extern "C" int
LLVMFuzzerInitialize(int *argc, char ***argv)
{
  // The set-up needs MPI as deepdraw's main() starts it; never finalised,
  // libFuzzer ends the process itself.
  new dealii::Utilities::MPI::MPI_InitFinalize(*argc, *argv, 1);
  dealii::deal_II_exceptions::disable_abort_on_exception();
  dealii::deal_II_exceptions::suppress_stacktrace_in_exceptions();
  return 0;
}

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  static const std::string path
    = "fuzz_input_" + std::to_string(::getpid()) + ".prm";
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char *>(data),
              static_cast<std::streamsize>(size));
  }
  try
  {
    dealii::ParameterHandler prm;
    deepdraw::problem::FormingProblem::declare_parameters(prm);
    deepdraw::io::read_parameter_file(prm, path);
    prm.enter_subsection("Geometry");
    const double cells = double(prm.get_integer("Elements along x"))
                         * prm.get_integer("Elements along y")
                         * prm.get_integer("Layers through thickness");
    prm.leave_subsection();
    if (cells > max_cells)
      return 0;
    deepdraw::problem::FormingProblem problem(prm, ".");
  }
  catch (const deepdraw::InputError &)
  {
  }
  catch (const dealii::ExceptionBase &)
  {
  }
  catch (const std::exception &error)
  {
    std::cerr << "fuzz: unexpected " << typeid(error).name() << ": "
              << error.what() << "\n";
    std::abort();
  }
  return 0;
}
