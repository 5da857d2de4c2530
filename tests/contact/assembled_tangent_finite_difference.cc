// The assembled Newton matrix of the full contact problem (sheet, punch,
// die, force-controlled blank holder, Coulomb friction) is the derivative of
// the assembled residual (doc/theory_material.md, doc/theory_contact.md):
// central finite differences of every column, on a coarse square cup with mixed
// open/stick/slip pairs. Columns whose difference crosses a kink of the contact
// law (a pair changing state between x - h and x + h) are skipped and counted.
#include "test_utilities.h"

#include <deal.II/base/mpi.h>
#include <deepdraw/problem/forming_problem.h>
#include <random>

using namespace dealii;
using namespace deepdraw;

namespace
{
  const char *prm_text = R"(
subsection Geometry
  set Length = 75
  set Width = 75
  set Thickness = 0.81
  set Elements along x = 6
  set Elements along y = 6
  set Layers through thickness = 1
end
# Enhanced parameters solved to round-off: the condensed residual is then a
# function of the unknowns alone (the default 1e-4 moves it by O(1e-8)).
subsection Finite element
  set Element = incompatible modes
  set Enhanced tolerance = 1e-13
end
subsection Contact
  set Friction coefficient = 0.162
  subsection Tool 1
    set Name = punch
    set Geometry = square cup punch
    set Sheet surface = top
    set Translation = 0; 0; -t
  end
  subsection Tool 2
    set Name = die
    set Geometry = square cup die
    set Sheet surface = bottom
  end
  subsection Tool 3
    set Name = blank holder
    set Geometry = square cup blank holder
    set Sheet surface = top
    set Control = force
  end
end
subsection Process
  set Blank holder force = 4900
end
subsection Output
  set Output directory = contact-tangent-test-output
  set Write VTU = false
end
)";
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ParameterHandler                 prm;
  problem::FormingProblem::declare_parameters(prm);
  prm.parse_input_from_string(prm_text);
  problem::FormingProblem forming_problem(prm);
  forming_problem.increment_solver().prepare_increment(0., 0.5);

  const types::global_dof_index n_u
    = forming_problem.access().sheet().n_displacement_dofs();
  Vector<double> x(forming_problem.access().state().converged_solution);
  const types::global_dof_index n = x.size();
  // A state with pairs in every state: the centre pushed down under the
  // punch, a random wrinkle, random contact forces, the holder pressed in.
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  const auto &vertices = forming_problem.access().sheet().initial_vertices();
  const auto &dofs     = forming_problem.access().sheet().dof_handler();
  for (const auto &cell : dofs.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
    {
      const Point<3> &X = vertices[cell->vertex_index(v)];
      for (unsigned int c = 0; c < 3; ++c)
        x[cell->vertex_dof_index(v, c)] = 0.05 * uniform(random);
      if (X[0] < 40 && X[1] < 40)
        x[cell->vertex_dof_index(v, 2)] -= 0.45;
    }
  for (types::global_dof_index i = n_u; i + 1 < n; ++i)
    x[i] = 2e4 * uniform(random);
  x[n - 1] = -0.01; // holder position along its axis

  Vector<double>     residual(n), plus(n), minus(n);
  FullMatrix<double> tangent;
  deepdraw_test::check_true("residual evaluates",
                            forming_problem.increment_solver()
                              .evaluate_residual(x, residual, &tangent));
  const unsigned int stick = forming_problem.access().contact().n_stick();
  const unsigned int slip  = forming_problem.access().contact().n_slip();
  std::cout << "pairs in stick " << stick << ", in slip " << slip << std::endl;
  deepdraw_test::check_true("some pairs stick and some slip",
                            stick > 0 && slip > 0);

  // Row scale: the largest entry of each row.
  std::vector<double> row_scale(n, 0.);
  for (types::global_dof_index i = 0; i < n; ++i)
    for (types::global_dof_index j = 0; j < n; ++j)
      row_scale[i] = std::max(row_scale[i], std::abs(tangent(i, j)));

  double       worst     = 0.;
  unsigned int skipped   = 0;
  unsigned int worst_row = 0, worst_column = 0;
  for (types::global_dof_index j = 0; j < n; ++j)
  {
    // Displacements and positions in mm, forces in N.
    const double   h         = (j >= n_u && j + 1 < n) ? 1e-3 : 1e-7;
    Vector<double> perturbed = x;
    perturbed[j] += h;
    forming_problem.increment_solver().evaluate_residual(perturbed,
                                                         plus,
                                                         nullptr);
    const unsigned int stick_plus
      = forming_problem.access().contact().n_stick();
    perturbed[j] -= 2 * h;
    forming_problem.increment_solver().evaluate_residual(perturbed,
                                                         minus,
                                                         nullptr);
    if (stick_plus != forming_problem.access().contact().n_stick()
        || stick_plus != stick)
    {
      ++skipped;
      continue;
    }
    for (types::global_dof_index i = 0; i < n; ++i)
    {
      const double fd = (plus[i] - minus[i]) / (2 * h);
      const double error
        = std::abs(fd - tangent(i, j)) / std::max(row_scale[i], 1e-300);
      if (error > worst)
      {
        worst        = error;
        worst_row    = i;
        worst_column = j;
      }
    }
  }
  std::cout << n << " unknowns (" << n_u << " displacements), " << skipped
            << " columns skipped at kinks; worst entry at row " << worst_row
            << ", column " << worst_column << std::endl;
  deepdraw_test::check_true("few columns cross a kink", skipped < n / 20);
  // Central differences: truncation ~h^2 |r'''|, round-off ~1e-16 |r| / h;
  // 1e-6 of the row's largest entry leaves room for both.
  deepdraw_test::check_close("max |K - K_fd| / row scale", worst, 0., 1e-6);
  return deepdraw_test::summary();
}
