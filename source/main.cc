// deepdraw: implicit simulation of sheet-metal deep drawing.
//   deepdraw FILE.prm [--output-directory DIR] [--resume] [--quiet]
//   deepdraw --help
//   deepdraw --print-parameters
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/problem/forming_problem.h>
#include <deepdraw/problem/stop_request.h>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace
{
  const char *usage
    = "usage: deepdraw FILE.prm [--output-directory DIR] [--resume] "
      "[--quiet]\n"
      "       deepdraw --print-parameters   print all parameters, documented,\n"
      "                                     with their default values\n"
      "       deepdraw --help               print this text\n"
      "\n"
      "Runs the forming simulation described by FILE.prm and writes the "
      "results\n"
      "(solution.pvd + VTU for ParaView, CSV tables) to the output directory.\n"
      "  --resume   continue from the checkpoint in the output directory\n"
      "  --quiet    print only the summary, not a line per increment\n"
      "SIGINT or SIGTERM stop after the current increment with a checkpoint.\n"
      "Exit codes: 0 done, 1 bad command line, 2 bad input, 3 the run could "
      "not\n"
      "be completed (results of the converged increments are kept).\n";

  // deal.II's exception text without its source-location preamble.
  std::string
  deal_ii_message(const dealii::ExceptionBase &exception)
  {
    std::ostringstream text;
    exception.print_info(text);
    std::string message = text.str();
    while (!message.empty()
           && (message.back() == '\n' || message.back() == ' '))
      message.pop_back();
    const auto start = message.find_first_not_of(" \n");
    return start == std::string::npos ? message : message.substr(start);
  }
} // namespace


int
main(int argc, char *argv[])
{
  using namespace deepdraw;
  // As many threads as cores (or DEAL_II_NUM_THREADS): the element
  // assembly runs in a WorkStream loop whose copier adds the cells in a
  // fixed order, so the results do not depend on the thread count (D61).
  dealii::Utilities::MPI::MPI_InitFinalize
    mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  dealii::deal_II_exceptions::disable_abort_on_exception();

  std::string         prm_file, output_directory;
  problem::RunOptions options;
  for (int i = 1; i < argc; ++i)
  {
    const std::string argument = argv[i];
    if (argument == "--help" || argument == "-h")
    {
      std::cout << usage;
      return 0;
    }
    else if (argument == "--print-parameters")
    {
      dealii::ParameterHandler prm;
      problem::FormingProblem::declare_parameters(prm);
      prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
      return 0;
    }
    else if (argument == "--output-directory" && i + 1 < argc)
      output_directory = argv[++i];
    else if (argument == "--resume")
      options.resume = true;
    else if (argument == "--quiet")
      options.quiet = true;
    else if (!argument.empty() && argument[0] != '-' && prm_file.empty())
      prm_file = argument;
    else
    {
      std::cerr << "deepdraw: unknown argument '" << argument << "'\n" << usage;
      return 1;
    }
  }
  if (prm_file.empty())
  {
    std::cerr << usage;
    return 1;
  }

  std::unique_ptr<problem::FormingProblem> forming_problem;
  try
  {
    if (!std::ifstream(prm_file))
      throw InputError("cannot open the parameter file '" + prm_file + "'");
    dealii::ParameterHandler prm;
    problem::FormingProblem::declare_parameters(prm);
    prm.parse_input(prm_file);
    if (!output_directory.empty())
    {
      prm.enter_subsection("Output");
      prm.set("Output directory", output_directory);
      prm.leave_subsection();
    }
    const auto        slash = prm_file.find_last_of('/');
    const std::string input_directory
      = slash == std::string::npos ? "." : prm_file.substr(0, slash);
    forming_problem
      = std::make_unique<problem::FormingProblem>(prm, input_directory);
  }
  catch (const InputError &error)
  {
    std::cerr << "deepdraw: error in the input: " << error.what() << std::endl;
    return 2;
  }
  catch (const dealii::ExceptionBase &error)
  {
    std::cerr << "deepdraw: error in " << prm_file << ": "
              << deal_ii_message(error) << std::endl;
    return 2;
  }

  problem::install_stop_handlers();
  try
  {
    forming_problem->run(options);
  }
  catch (const InputError &error)
  {
    std::cerr << "deepdraw: error in the input: " << error.what() << std::endl;
    return 2;
  }
  catch (const problem::RunFailure &failure)
  {
    std::cerr << "deepdraw: the run stopped: " << failure.what() << std::endl;
    return 3;
  }
  catch (const std::exception &error)
  {
    std::cerr << "deepdraw: the run stopped: " << error.what() << std::endl;
    return 3;
  }
  return 0;
}
