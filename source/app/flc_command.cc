// deepdraw --flc FILE.prm (doc/user_guide.md §8).
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/app/flc_command.h>
#include <deepdraw/formability/flc_files.h>
#include <deepdraw/formability/forming_limit_curve_factory.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/output_error.h>
#include <deepdraw/io/parameter_file.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/problem/forming_problem.h>
#include <filesystem>
#include <iostream>

namespace deepdraw
{
  namespace app
  {
    namespace
    {
      struct FlcInput
      {
        formability::FormabilityParameters              formability;
        material::MaterialParameters                    material;
        std::unique_ptr<formability::FormingLimitCurve> curve;
        std::string                                     directory;
      };

      // Everything that can be wrong with the input, before any output.
      FlcInput
      read_input(const std::string &prm_file,
                 const std::string &output_directory)
      {
        // Every subsection of the program, Formability with them (declared
        // by the post-processor "forming limits").
        dealii::ParameterHandler prm;
        problem::FormingProblem::declare_parameters(prm);
        io::read_parameter_file(prm, prm_file);
        const auto        slash = prm_file.find_last_of('/');
        const std::string input_directory
          = slash == std::string::npos ? "." : prm_file.substr(0, slash);

        FlcInput input;
        prm.enter_subsection("Material");
        input.material.parse_parameters(prm);
        prm.leave_subsection();
        prm.enter_subsection("Formability");
        input.formability.parse_parameters(prm, input_directory);
        prm.leave_subsection();
        prm.enter_subsection("Geometry");
        const double thickness = prm.get_double("Thickness");
        prm.leave_subsection();
        prm.enter_subsection("Output");
        input.directory = output_directory.empty() ? prm.get("Output directory")
                                                   : output_directory;
        prm.leave_subsection();
        input.curve
          = formability::create_required_forming_limit_curve(input.formability,
                                                             input.material,
                                                             thickness);
        return input;
      }
    } // namespace


    int
    run_flc_command(const std::string &prm_file,
                    const std::string &output_directory)
    {
      FlcInput input;
      try
      {
        input = read_input(prm_file, output_directory);
      }
      catch (const InputError &error)
      {
        std::cerr << "deepdraw: error in the input: "
                  << io::one_line(error.what()) << std::endl;
        return 2;
      }
      catch (const dealii::ExceptionBase &error)
      {
        std::cerr << "deepdraw: error in the input: "
                  << io::deal_ii_message(error) << std::endl;
        return 2;
      }
      try
      {
        std::filesystem::create_directories(input.directory);
      }
      catch (const std::exception &error)
      {
        std::cerr << "deepdraw: error in the input: cannot create the output "
                     "directory '"
                  << io::one_line(input.directory, 300)
                  << "': " << io::one_line(error.what()) << std::endl;
        return 2;
      }
      try
      {
        const std::string plot
          = formability::write_flc_files(*input.curve,
                                         input.formability.zones,
                                         input.directory);
        std::cout << "deepdraw --flc: " << input.curve->description() << "; "
                  << input.directory << "/flc.csv written, " << plot
                  << std::endl;
      }
      catch (const std::exception &error)
      {
        std::cerr << "deepdraw: flc.csv could not be written: "
                  << io::one_line(error.what()) << std::endl;
        return 3;
      }
      return 0;
    }
  } // namespace app
} // namespace deepdraw
