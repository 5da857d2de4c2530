// The checks that no tool passes through the sheet unseen
// (ContactCoupling::check_tool_sides / check_tool_motion, doc/decisions.md
// D56), on the square-cup punch and die over a 6 x 6 x 2 quarter blank at
// load 0:
// - a bottom node pushed 1 mm into the die (more than half the 0.81 mm
//   sheet, the threshold) is reported with the tool's name; pushed 0.2 mm
//   (below the threshold) or not at all, nothing is reported;
// - the punch (translation -t) moving 5 mm in one increment is reported
//   against the 2 mm search distance, moving 1 mm is not.
#include "contact/forming_test_tools.h"
#include "test_utilities.h"

#include <deal.II/base/mpi.h>

using namespace dealii;
using namespace deepdraw;

namespace
{
  const char *prm_text = R"(
subsection Geometry
  set Length = 75
  set Width = 75
  set Thickness = 0.81
  set Layers through thickness = 2
  set Elements along x = 6
  set Elements along y = 6
  set Symmetry planes = x, y
end
subsection Contact
  subsection Tool 1
    set Name          = punch
    set Geometry      = square cup punch
    set Sheet surface = top
    set Translation   = 0; 0; -t
  end
  subsection Tool 2
    set Name          = die
    set Geometry      = square cup die
    set Sheet surface = bottom
    set Translation   = 0; 0; 0
  end
end
)";
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Only the set-up is needed (the tools at load 0), no increment.
  ParameterHandler prm;
  problem::FormingProblem::declare_parameters(prm);
  prm.parse_input_from_string(prm_text);
  forming_test::redirect_output(prm, "tool-side-checks-output");
  const auto  forming_problem = std::make_unique<problem::FormingProblem>(prm);
  const auto &contact         = forming_problem->access().contact();
  const auto &vertices        = forming_problem->access().state().vertices;
  const auto &X = forming_problem->access().sheet().initial_vertices();
  const auto  n_unknown
    = forming_problem->access().state().converged_solution.size();

  // A bottom vertex over the die's flat face (x = 62.5, y = 0, z = 0).
  unsigned int flange_vertex = numbers::invalid_unsigned_int;
  for (unsigned int v = 0; v < X.size(); ++v)
    if (std::abs(X[v][0] - 62.5) < 1e-9 && std::abs(X[v][1]) < 1e-9
        && std::abs(X[v][2]) < 1e-9)
      flange_vertex = v;
  deepdraw_test::check_true("a bottom vertex at (62.5, 0, 0)",
                            flange_vertex != numbers::invalid_unsigned_int);
  // Its displacement dofs.
  std::vector<types::global_dof_index> z_dofs(3, numbers::invalid_dof_index);
  for (const auto &cell :
       forming_problem->access().sheet().dof_handler().active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
      if (cell->vertex_index(v) == flange_vertex)
        for (unsigned int c = 0; c < 3; ++c)
          z_dofs[c] = cell->vertex_dof_index(v, c);

  const double   thickness = 0.81;
  Vector<double> solution(n_unknown);
  deepdraw_test::check_true(
    "no displacement: nothing reported",
    contact.check_tool_sides(vertices, solution, thickness).empty());
  solution[z_dofs[2]] = -0.2;
  deepdraw_test::check_true(
    "0.2 mm into the die: below the threshold",
    contact.check_tool_sides(vertices, solution, thickness).empty());
  solution[z_dofs[2]] = -1.;
  const std::string message
    = contact.check_tool_sides(vertices, solution, thickness);
  std::cout << "  message: " << message << std::endl;
  deepdraw_test::check_true("1 mm into the die: reported with the tool",
                            message.find("inside tool 'die'")
                              != std::string::npos);

  const std::string motion = contact.check_tool_motion(0., 5.);
  std::cout << "  message: " << motion << std::endl;
  deepdraw_test::check_true("the punch moving 5 mm is reported",
                            motion.find("tool 'punch' moves 5 mm")
                              != std::string::npos);
  deepdraw_test::check_true("the punch moving 1 mm is not",
                            contact.check_tool_motion(0., 1.).empty());
  return deepdraw_test::summary();
}
