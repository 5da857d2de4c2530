// The program deepdraw as a function (source/main.cc is MPI, signals and
// this): the command line (doc/user_guide.md §1), reading and checking the
// input, the run, and the exit code of every outcome (§5). A function so
// that the hostile-input tests (tests/input/) can run hundreds of cases in
// one process.
#include <algorithm>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/app/command_line.h>
#include <deepdraw/app/commands.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/output_directory.h>
#include <deepdraw/io/output_error.h>
#include <deepdraw/io/output_lock.h>
#include <deepdraw/io/parameter_file.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/regular_file.h>
#include <deepdraw/parallel/ranks.h>
#include <deepdraw/parallel/run_agreement.h>
#include <deepdraw/problem/forming_problem.h>
#include <deepdraw/state/stop_request.h>
#include <iostream>
#include <new>
#include <string>

namespace deepdraw
{
  namespace app
  {
    namespace
    {
      // clang-format off
      const char *usage =
        "usage: deepdraw FILE.prm [--output-directory DIR] [--resume] [--quiet]\n"
        "       deepdraw --check FILE.prm     read and check the input,\n"
        "                                     write nothing\n"
        "       deepdraw FILE.prm [--output-directory DIR]\n"
        "           --study \"Subsection/Parameter = v1, v2, ...\" ...\n"
        "                                     refinement study: one run per\n"
        "                                     value (options of the same length\n"
        "                                     vary together); study.csv and\n"
        "                                     study.png in the output directory\n"
        "       deepdraw --flc FILE.prm [--output-directory DIR]\n"
        "                                     the forming-limit curve of FILE.prm's\n"
        "                                     subsection Formability: flc.csv and\n"
        "                                     flc.png in the output directory\n"
        "       deepdraw --write-square-cup-tools DIR [FILE.prm]\n"
        "                                     write the built-in square-cup tools\n"
        "                                     as STEP and IGES files\n"
        "       deepdraw --print-parameters   print all parameters, documented,\n"
        "                                     with their default values\n"
        "       deepdraw --help               print this text\n"
        "\n"
        "Runs the forming simulation described by FILE.prm and writes the results\n"
        "(solution.pvd + VTU for ParaView, CSV tables) to the output directory.\n"
        "  --resume   continue from the checkpoint in the output directory\n"
        "  --quiet    print only the summary, not a line per increment\n"
        "SIGINT, SIGTERM, SIGHUP or SIGQUIT stop after the current increment with a\n"
        "checkpoint.\n"
        "Exit codes: 0 done, 1 bad command line, 2 bad input, 3 the run could not\n"
        "be completed (results of the converged increments are kept).\n";
      // clang-format on

      int
      command_line_error(const std::string &message)
      {
        std::cerr << "deepdraw: " << io::one_line(message) << "\n" << usage;
        return 1;
      }

      // Every message is one printable line: it may quote input
      // (doc/user_guide.md §5.2).
      int
      input_error(const std::string &message)
      {
        std::cerr << "deepdraw: error in the input: " << io::one_line(message)
                  << std::endl;
        return 2;
      }

      int
      run_stopped(const std::string &message)
      {
        std::cerr << "deepdraw: the run stopped: " << io::one_line(message)
                  << std::endl;
        return 3;
      }

      bool
      has(const std::vector<std::string> &arguments, const char *flag)
      {
        return std::find(arguments.begin(), arguments.end(), flag)
               != arguments.end();
      }

      // The run: a failure after the output has started is exit code 3;
      // SIGINT, SIGTERM, SIGHUP and SIGQUIT stop it cleanly with a
      // checkpoint (D55, D163).
      int
      run_model(problem::FormingProblem   &forming_problem,
                const problem::RunOptions &options)
      {
        try
        {
          forming_problem.run(options);
        }
        catch (const parallel::RankFailure &failure)
        {
          return failure.code;
        }
        catch (const InputError &error)
        {
          return input_error(error.what());
        }
        catch (const io::OutputError &error)
        {
          return run_stopped(error.what());
        }
        catch (const problem::RunFailure &failure)
        {
          return run_stopped(failure.what());
        }
        catch (const dealii::ExceptionBase &error)
        {
          return run_stopped(io::deal_ii_message(error));
        }
        catch (const std::bad_alloc &)
        {
          return run_stopped("out of memory; what was written up to the last "
                             "converged increment stays valid");
        }
        catch (const std::exception &error)
        {
          return run_stopped(error.what());
        }
        return 0;
      }
    } // namespace


    int
    run_command_line(const std::vector<std::string> &arguments)
    {
      // Under mpirun the ranks share a run; the other commands are rank
      // 0's alone (D199).
      if (parallel::n_ranks() > 1)
      {
        if (has(arguments, "--study"))
          return input_error(
            "--study runs on one MPI rank: start it without mpirun (its runs "
            "are not launched under mpirun yet)");
        if ((!arguments.empty() && arguments[0] == "--write-square-cup-tools")
            || has(arguments, "--flc") || has(arguments, "--check")
            || has(arguments, "--print-parameters") || has(arguments, "--help")
            || has(arguments, "-h"))
          if (!parallel::is_root())
            return 0;
      }
      if (!arguments.empty() && arguments[0] == "--write-square-cup-tools")
        return write_square_cup_tools(arguments);
      if (std::find(arguments.begin(), arguments.end(), "--flc")
          != arguments.end())
        return flc_command(arguments);
      if (std::find(arguments.begin(), arguments.end(), "--study")
          != arguments.end())
        return run_study_command(arguments);
      std::string         prm_file, output_directory;
      bool                check_only = false, output_directory_given = false;
      problem::RunOptions options;
      const std::size_t   argc = arguments.size();
      for (std::size_t i = 0; i < argc; ++i)
      {
        const std::string &argument = arguments[i];
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
        else if (argument == "--check")
          check_only = true;
        else if (argument == "--resume")
          options.resume = true;
        else if (argument == "--quiet")
          options.quiet = true;
        else if (argument == "--output-directory")
        {
          if (i + 1 >= argc || arguments[i + 1].empty())
            return command_line_error("--output-directory needs a directory "
                                      "name after it");
          if (output_directory_given)
            return command_line_error("--output-directory given twice");
          output_directory       = arguments[++i];
          output_directory_given = true;
        }
        else if (!argument.empty() && argument[0] != '-' && prm_file.empty())
          prm_file = argument;
        else if (!argument.empty() && argument[0] != '-')
          return command_line_error("more than one parameter file: '" + prm_file
                                    + "' and '" + argument + "'");
        else
          return command_line_error("unknown argument '" + argument + "'");
      }
      if (prm_file.empty())
        return command_line_error("no parameter file given");

      // Reading and checking the input: exit code 2, nothing written (D11).
      std::unique_ptr<problem::FormingProblem> forming_problem;
      try
      {
        dealii::ParameterHandler prm;
        problem::FormingProblem::declare_parameters(prm);
        io::read_parameter_file(prm, prm_file);
        if (output_directory_given)
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
        // --check --resume: the checkpoint too, as the resume would (D160).
        if (check_only && options.resume)
          forming_problem->check_resume();
        // --check: what the run would refuse in its output directory: one
        // it cannot make or write in, a live lock (D179) and a named pipe
        // where it writes (D164).
        if (check_only)
        {
          prm.enter_subsection("Output");
          const std::string directory = prm.get("Output directory");
          prm.leave_subsection();
          io::check_output_directory(directory, "Output/Output directory");
          io::OutputLock::check_free(directory, "Output/Output directory");
          io::check_output_entries(directory);
        }
      }
      catch (const InputError &error)
      {
        return input_error(error.what());
      }
      catch (const dealii::ExceptionBase &error)
      {
        return input_error(prm_file + ": " + io::deal_ii_message(error));
      }
      catch (const std::bad_alloc &)
      {
        // The mesh size is checked against the memory before the mesh is
        // made (D53); this is what the estimate did not foresee.
        return input_error(
          "not enough memory to set up the problem of " + prm_file
          + "; use a coarser mesh (Geometry/Elements along x, y, Layers "
            "through thickness)");
      }
      catch (const std::exception &error)
      {
        return input_error(prm_file + ": " + error.what());
      }
      if (check_only)
      {
        std::cout << "deepdraw: " << io::one_line(prm_file)
                  << (options.resume
                        ? ": the input and the checkpoint are valid"
                        : ": the input is valid")
                  << std::endl;
        return 0;
      }

      state::install_stop_handlers();
      const int code = run_model(*forming_problem, options);
      // Under mpirun a rank that stops may do so alone (rank 0's disk is
      // full): the model's MUMPS instances are released collectively, so
      // they are left to the end of the process (D199).
      if (code != 0 && parallel::n_ranks() > 1)
        (void)forming_problem.release();
      return code;
    }
  } // namespace app
} // namespace deepdraw
