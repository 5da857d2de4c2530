// The commands of deepdraw beside a run: --write-square-cup-tools, --flc
// and --study (doc/user_guide.md §1, §4.2, §8, doc/tool_files.md "CAD
// tools").
#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/app/commands.h>
#include <deepdraw/app/flc_command.h>
#include <deepdraw/app/study.h>
#include <deepdraw/geometry/cad_tool_writer.h>
#include <deepdraw/geometry/square_cup_tools.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/parameter_file.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/problem/forming_problem.h>
#include <iostream>

namespace deepdraw
{
  namespace app
  {
    // --write-square-cup-tools DIR [FILE.prm]: the built-in tools as STEP and
    // IGES files (doc/tool_files.md, CAD tools), to check the CAD reader
    // against the exact builder or to start a CAD model from.
    int
    write_square_cup_tools(const std::vector<std::string> &arguments)
    {
      if (arguments.size() < 2 || arguments.size() > 3 || arguments[1].empty()
          || arguments[1][0] == '-')
      {
        std::cerr << "deepdraw: usage: deepdraw --write-square-cup-tools DIR "
                     "[FILE.prm]\n";
        return 1;
      }
      const std::string &directory = arguments[1];
      const std::string  prm_file  = arguments.size() == 3 ? arguments[2] : "";
      try
      {
        dealii::ParameterHandler prm;
        problem::FormingProblem::declare_parameters(prm);
        if (!prm_file.empty())
          io::read_parameter_file(prm, prm_file);
        geometry::SquareCupToolParameters tools;
        tools.parse_parameters(prm);
        prm.enter_subsection("Geometry");
        const double thickness = prm.get_double("Thickness");
        prm.leave_subsection();
        for (const std::string &file : geometry::write_cad_tool_files(
               geometry::build_square_cup_tools(tools, thickness),
               directory))
          std::cout << "deepdraw: wrote " << file << std::endl;
      }
      catch (const InputError &error)
      {
        std::cerr << "deepdraw: error in the input: "
                  << io::one_line(error.what()) << std::endl;
        return 2;
      }
      catch (const dealii::ExceptionBase &error)
      {
        std::cerr << "deepdraw: error in " << prm_file << ": "
                  << io::deal_ii_message(error) << std::endl;
        return 2;
      }
      catch (const std::exception &error)
      {
        std::cerr << "deepdraw: cannot write the tools to " << directory << ": "
                  << io::one_line(error.what()) << std::endl;
        return 2;
      }
      return 0;
    }

    // --flc FILE.prm [--output-directory DIR], in any order.
    int
    flc_command(const std::vector<std::string> &arguments)
    {
      std::string prm_file, output_directory;
      bool        output_directory_given = false;
      for (std::size_t i = 0; i < arguments.size(); ++i)
      {
        const std::string &argument = arguments[i];
        if (argument == "--flc")
          continue;
        if (argument == "--output-directory" && i + 1 < arguments.size()
            && !arguments[i + 1].empty() && !output_directory_given)
        {
          output_directory       = arguments[++i];
          output_directory_given = true;
        }
        else if (!argument.empty() && argument[0] != '-' && prm_file.empty())
          prm_file = argument;
        else
        {
          std::cerr << "deepdraw: --flc: unknown, repeated or incomplete "
                       "argument '"
                    << io::one_line(argument)
                    << "'; usage: deepdraw --flc FILE.prm "
                       "[--output-directory DIR]\n";
          return 1;
        }
      }
      if (prm_file.empty())
      {
        std::cerr << "deepdraw: --flc needs a parameter file; usage: deepdraw "
                     "--flc FILE.prm [--output-directory DIR]\n";
        return 1;
      }
      return run_flc_command(prm_file, output_directory);
    }


    // FILE.prm [--output-directory DIR] --study "..." [--study "..."]
    int
    run_study_command(const std::vector<std::string> &arguments)
    {
      std::string              prm_file, output_directory;
      std::vector<std::string> study_options;
      for (std::size_t i = 0; i < arguments.size(); ++i)
      {
        const std::string &argument = arguments[i];
        if (argument == "--study" && i + 1 < arguments.size())
          study_options.push_back(arguments[++i]);
        else if (argument == "--output-directory" && i + 1 < arguments.size()
                 && !arguments[i + 1].empty())
          output_directory = arguments[++i];
        else if (!argument.empty() && argument[0] != '-' && prm_file.empty())
          prm_file = argument;
        else
        {
          std::cerr << "deepdraw: --study: unknown or incomplete argument '"
                    << io::one_line(argument) << "'\n";
          return 1;
        }
      }
      if (prm_file.empty())
      {
        std::cerr << "deepdraw: --study needs a parameter file\n";
        return 1;
      }
      return run_study(prm_file, output_directory, study_options);
    }
  } // namespace app
} // namespace deepdraw
