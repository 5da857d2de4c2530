// Adaptive refinement of a block under a uniform stress (issue 13, test a;
// doc/theory.md §8): a 2 x 2 x 2 block of 1 mm cells is stretched along x
// into the plastic range (Hill'48 + Swift, incompatible modes) in four
// increments; after the second, subsection Adaptivity refines the corner
// cell x, y, z < 1 isotropically (hanging nodes on three of its faces). The
// state is homogeneous, so
// - the transfer changes no stress value (constant fields are exact) and the
//   transferred state is in equilibrium: the re-equilibration starts at a
//   force residual of round-off size and needs at most one Newton iteration;
// - at the end every quadrature point of the refined mesh has the stress,
//   back stress and equivalent plastic strain of the same run on the fixed
//   mesh, and the reaction of the face xmax is the same.
// Tolerances: the two runs differ only in round-off (measured 2e-15
// relative on the stress, 5e-14 initial residual); 1e-11 is a few thousand
// times that and far below what a real transfer error (0.18 h of a
// gradient, D57) or a missing hanging-node constraint would give.
#include "test_utilities.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/problem/forming_problem.h>
#include <memory>

using namespace dealii;
using namespace deepdraw;

namespace
{
  const char *block_parameters = R"(
subsection Geometry
  set Length                   = 2
  set Width                    = 2
  set Thickness                = 2
  set Elements along x         = 2
  set Elements along y         = 2
  set Layers through thickness = 2
  set Symmetry planes          = x, y
end
subsection Boundary conditions
  set Prescribed displacements = zmin: uz = 0; xmax: ux = 0.04*t
end
subsection Load stepping
  set Initial increment = 0.25
  set Maximum increment = 0.25
end
subsection Newton
  set Force tolerance      = 1e-10
  set Correction tolerance = 1e-10
end
subsection Output
  set Write VTU = false
end
)";

  std::unique_ptr<problem::FormingProblem>
  run(const bool adaptive, const std::string &directory)
  {
    ParameterHandler prm;
    problem::FormingProblem::declare_parameters(prm);
    prm.parse_input_from_string(block_parameters);
    prm.enter_subsection("Output");
    prm.set("Output directory", directory);
    prm.leave_subsection();
    prm.enter_subsection("Adaptivity");
    prm.set("Enabled", adaptive);
    prm.set("Refinement interval", "2");
    prm.set("Maximum level", "1");
    prm.set("Indicator", "region");
    prm.set("Region minimum", "0, 0, 0");
    prm.set("Region maximum", "1, 1, 1");
    prm.leave_subsection();
    auto problem = std::make_unique<problem::FormingProblem>(prm);
    problem->run(problem::RunOptions{false, true});
    return problem;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto fixed    = run(false, "output-uniform-stress-fixed");
  const auto adaptive = run(true, "output-uniform-stress-adaptive");

  const auto &records = adaptive->refinement_records();
  deepdraw_test::check_true("one refinement", records.size() == 1);
  if (records.size() != 1)
    return deepdraw_test::summary();
  const auto &record = records[0];
  std::cout << "refinement after increment " << record.increment << ": "
            << record.cells_before << " -> " << record.cells_after << " cells, "
            << record.hanging_vertices << " hanging vertices, initial residual "
            << record.initial_force_residual << ", " << record.iterations
            << " iteration(s)" << std::endl;
  deepdraw_test::check_true("8 -> 15 cells",
                            record.cells_before == 8
                              && record.cells_after == 15);
  deepdraw_test::check_true("hanging vertices", record.hanging_vertices > 0);
  deepdraw_test::check_close("transferred state in equilibrium",
                             record.initial_force_residual,
                             0.,
                             1e-11);
  deepdraw_test::check_true("at most one re-equilibration iteration",
                            record.iterations <= 1);

  // Every point against the fixed mesh's (homogeneous) point 0.
  const fe::QuadraturePointHistory &reference
    = fixed->access().state().history[0];
  const double scale        = reference.state.stress.norm();
  double       stress_error = 0., back_stress_error = 0., strain_error = 0.;
  for (const auto &point : adaptive->access().state().history)
  {
    stress_error
      = std::max(stress_error,
                 (point.state.stress - reference.state.stress).norm());
    back_stress_error = std::max(
      back_stress_error,
      (point.state.back_stress - reference.state.back_stress).norm());
    strain_error
      = std::max(strain_error,
                 std::abs(point.state.equivalent_plastic_strain
                          - reference.state.equivalent_plastic_strain));
  }
  deepdraw_test::check_true("plastic",
                            reference.state.equivalent_plastic_strain > 1e-3);
  deepdraw_test::check_close("stress at every point / |stress|",
                             stress_error / scale,
                             0.,
                             1e-11);
  deepdraw_test::check_close("back stress at every point / |stress|",
                             back_stress_error / scale,
                             0.,
                             1e-11);
  deepdraw_test::check_close("equivalent plastic strain at every point",
                             strain_error,
                             0.,
                             1e-11);
  const double fixed_force    = fixed->access().face_reaction(1)[0];
  const double adaptive_force = adaptive->access().face_reaction(1)[0];
  deepdraw_test::check_relative("reaction on xmax",
                                adaptive_force,
                                fixed_force,
                                1e-11);
  return deepdraw_test::summary();
}
