// A new result is one file with one registration (doc/architecture.md, "How
// to add a post-processor"): this test defines the post-processor "maximum
// plastic strain" here, registers it with DEEPDRAW_REGISTER_POSTPROCESSOR,
// and runs the tension bar of prm/tension_bar.prm (4 x 2 x 2 cells,
// homogeneous uniaxial tension along the rolling direction, Hill'48 +
// Swift) to t = 0.4 with only it listed. Checks:
// - its parameter (Postprocess/Maximum plastic strain/File name) is declared
//   with every other one, and the list in the prm chooses what is written:
//   its table and nothing of the default post-processors (no
//   statistics.csv, no solution.pvd);
// - a row at t = 0 and one per converged increment, with the largest
//   equivalent plastic strain of the bar, against the closed form of the
//   homogeneous state, epbar = (e - sigma/E)/sqrt(G + H) with
//   sigma = Y(epbar)/sqrt(G + H) and e = 0.5 t (tests/regression/
//   tension_bar.check.py): 1e-4 relative (measured 4.6e-5 at most, the
//   time integration of the hypoelastic law);
// - an unknown name in the list is refused naming the parameter.
#include "../test_utilities.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/io/csv_file.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/postprocess/interface.h>
#include <deepdraw/problem/forming_problem.h>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace dealii;
using namespace deepdraw;

namespace
{
  // The one file of the new result.
  class MaximumPlasticStrain : public postprocess::Interface
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Postprocess");
      prm.enter_subsection("Maximum plastic strain");
      prm.declare_entry("File name",
                        "maximum_plastic_strain.csv",
                        Patterns::FileName(),
                        "Its table in the output directory.");
      prm.leave_subsection();
      prm.leave_subsection();
    }

    void
    parse_parameters(ParameterHandler &prm) override
    {
      prm.enter_subsection("Postprocess");
      prm.enter_subsection("Maximum plastic strain");
      name = prm.get("File name");
      prm.leave_subsection();
      prm.leave_subsection();
    }

    void
    start(const postprocess::SimulationAccess &simulation,
          const bool                           resume) override
    {
      file.open(simulation.output_directory() + "/" + name,
                {"load", "maximum_plastic_strain"},
                resume);
    }

    void
    execute(const postprocess::SimulationAccess &simulation) override
    {
      double largest = 0.;
      for (const auto &point : simulation.state().history)
        largest = std::max(largest, point.state.equivalent_plastic_strain);
      file.add_row({simulation.state().load, largest});
    }

  private:
    std::string name;
    io::CsvFile file;
  };
} // namespace

DEEPDRAW_REGISTER_POSTPROCESSOR(MaximumPlasticStrain,
                                "maximum plastic strain",
                                "the largest equivalent plastic strain")

namespace
{
  const std::string prm_text = R"(
subsection Geometry
  set Length                   = 10
  set Width                    = 1
  set Thickness                = 1
  set Elements along x         = 4
  set Elements along y         = 2
  set Layers through thickness = 2
  set Symmetry planes          = x, y
end
subsection Finite element
  set Element = selective reduced
end
subsection Boundary conditions
  set Prescribed displacements = zmin: uz = 0; xmax: ux = 10*(exp(0.5*t)-1)
end
subsection Process
  set Final load = 0.4
end
subsection Load stepping
  set Initial increment = 0.02
  set Maximum increment = 0.05
end
subsection Postprocess
  set List of postprocessors = maximum plastic strain
end
)";

  // epbar of the homogeneous bar at logarithmic strain e (Hill'48 G, H and
  // Swift of the default aluminium): bisection on sigma.
  double
  closed_form_plastic_strain(const double e)
  {
    const double E = 71000., G = 0.5848, H = 0.4152;
    const double C = 576.79, eps0 = 0.01658, n = 0.3593;
    const double root = std::sqrt(G + H);
    double       low = C * std::pow(eps0, n) / root, high = E * e;
    if (high <= low)
      return 0.;
    for (unsigned int i = 0; i < 200; ++i)
    {
      const double sigma = 0.5 * (low + high);
      const double epbar = (e - sigma / E) / root;
      (sigma - C * std::pow(eps0 + epbar, n) / root > 0. ? high : low) = sigma;
    }
    return (e - low / E) / root;
  }
} // namespace


int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                output = "added-postprocessor-output";
  std::filesystem::remove_all(output);

  ParameterHandler prm;
  problem::FormingProblem::declare_parameters(prm);
  prm.parse_input_from_string(prm_text);
  prm.enter_subsection("Output");
  prm.set("Output directory", output);
  prm.leave_subsection();
  prm.enter_subsection("Postprocess");
  prm.enter_subsection("Maximum plastic strain");
  deepdraw_test::check_true("its parameter is declared with the others",
                            prm.get("File name")
                              == "maximum_plastic_strain.csv");
  prm.leave_subsection();
  prm.leave_subsection();
  problem::FormingProblem forming_problem(prm);
  forming_problem.run();

  deepdraw_test::check_true(
    "only the listed post-processors write",
    std::filesystem::exists(output + "/maximum_plastic_strain.csv")
      && !std::filesystem::exists(output + "/statistics.csv")
      && !std::filesystem::exists(output + "/solution.pvd"));
  std::ifstream table(output + "/maximum_plastic_strain.csv");
  std::string   line;
  std::getline(table, line);
  deepdraw_test::check_true("its header",
                            line == "load,maximum_plastic_strain");
  unsigned int rows = 0, plastic_rows = 0;
  while (std::getline(table, line))
  {
    std::istringstream fields(line);
    double             load = 0., strain = 0.;
    char               comma;
    fields >> load >> comma >> strain;
    ++rows;
    const double expected = closed_form_plastic_strain(0.5 * load);
    if (expected > 0.01)
    {
      ++plastic_rows;
      deepdraw_test::check_relative("epbar at t = " + std::to_string(load),
                                    strain,
                                    expected,
                                    1e-4);
    }
  }
  deepdraw_test::check_true(
    "a row at t = 0 and one per increment (" + std::to_string(rows) + ")",
    rows == forming_problem.access().state().increment_number + 1
      && plastic_rows > 5);

  // An unknown post-processor is refused, naming the parameter.
  ParameterHandler wrong;
  problem::FormingProblem::declare_parameters(wrong);
  wrong.parse_input_from_string(prm_text);
  wrong.enter_subsection("Postprocess");
  wrong.set("List of postprocessors", "maximum plastic strain, wrinkles");
  wrong.leave_subsection();
  std::string message;
  try
  {
    problem::FormingProblem refused(wrong);
  }
  catch (const InputError &error)
  {
    message = error.what();
  }
  deepdraw_test::check_true("unknown post-processor refused: " + message,
                            message.find("Postprocess/List of postprocessors: "
                                         "unknown post-processor 'wrinkles'")
                              == 0);
  return deepdraw_test::summary();
}
