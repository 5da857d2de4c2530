// adaptivity::tool_curvature_indicator (D94) on the flat quarter blank of the
// square cup (75 x 75 x 0.81 mm, 25 x 25 x 2 cells of 3 mm) under the
// shipped tools at their initial placement (punch profile radius 8 mm on
// the top face, die shoulder radius 8 mm below, flat holder), against the
// geometry worked out by hand:
// - punch profile: its circle has its centre 8 mm above the top face at
//   x = 27 (half width 35 - 8); the top vertex at x = 30 is 8.544 - 8 =
//   0.544 mm from it (< one thickness), x = 33 is 2 mm away (> 0.81). The
//   cells with a vertex at x = 30 and y <= 15 (the straight side, away from
//   the plan-view corner at y > 25) therefore have h kappa = 3/8 = 0.375, in
//   both layers (the column);
// - die shoulder: centre 8 mm below the bottom face at x = 45 (opening 37 +
//   8); the bottom vertex at x = 42 is 0.544 mm from it, x = 39 2 mm: the
//   cells with a vertex at x = 42 and y <= 15 have 0.375 too;
// - under the punch flat (x, y <= 24) and under the flat holder and die
//   (x >= 51): 0 (round-off of the flat rational patches: 6e-19).
// The curvature comes from the rational Bézier arcs, exact to round-off
// (errors of 3e-16 seen): tolerance 1e-12, room for the Newton projection
// of the foot points on other platforms.
#include "test_utilities.h"

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deepdraw/adaptivity/refinement_indicator.h>
#include <deepdraw/geometry/square_cup_tools.h>

using namespace dealii;
using namespace deepdraw;
using namespace deepdraw_test;

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     thickness = 0.81;
  Triangulation<3>                 mesh;
  // colorize: boundary ids 4 bottom (z = 0), 5 top (z = thickness).
  GridGenerator::subdivided_hyper_rectangle(mesh,
                                            {25, 25, 2},
                                            Point<3>(0., 0., 0.),
                                            Point<3>(75., 75., thickness),
                                            true);
  const geometry::SquareCupToolParameters parameters;
  const std::vector<geometry::RigidTool>  tools
    = geometry::build_square_cup_tools(parameters, thickness);
  // punch, die, blank holder: top, bottom, top.
  const std::vector<double> ratio
    = adaptivity::tool_curvature_indicator(mesh, tools, {5, 4, 5}, thickness);

  unsigned int punch_cells = 0, die_cells = 0, flat_cells = 0;
  for (const auto &cell : mesh.active_cell_iterators())
  {
    double x_min = 1e9, x_max = -1e9, y_max = -1e9;
    for (const unsigned int v : cell->vertex_indices())
    {
      x_min = std::min(x_min, cell->vertex(v)[0]);
      x_max = std::max(x_max, cell->vertex(v)[0]);
      y_max = std::max(y_max, cell->vertex(v)[1]);
    }
    const double value = ratio[cell->active_cell_index()];
    const auto   has_x
      = [&](const double x) { return x_min <= x + 1e-9 && x_max >= x - 1e-9; };
    const std::string where = "cell at x " + std::to_string(x_min) + "-"
                              + std::to_string(x_max)
                              + ", y <= " + std::to_string(y_max) + ", z "
                              + std::to_string(cell->center()[2]);
    if (y_max <= 15. + 1e-9 && has_x(30.))
    {
      check_close(where + " (punch radius)", value, 3. / 8., 1e-12);
      ++punch_cells;
    }
    else if (y_max <= 15. + 1e-9 && has_x(42.))
    {
      check_close(where + " (die shoulder)", value, 3. / 8., 1e-12);
      ++die_cells;
    }
    else if ((x_max <= 24. + 1e-9 && y_max <= 24. + 1e-9)
             || x_min >= 51. - 1e-9)
    {
      // Printed only if it fails: 528 cells.
      if (std::abs(value) > 1e-12)
        check_close(where + " (flat tools)", value, 0., 1e-12);
      ++flat_cells;
    }
  }
  // 5 rows in y (0..15) x 2 cells in x x 2 layers each; the flat cells:
  // 8 x 8 under the punch and 8 x 25 in the flange, 2 layers.
  check_true("punch-radius cells checked: 20", punch_cells == 20);
  check_true("die-shoulder cells checked: 20", die_cells == 20);
  check_true("flat-tool cells checked: 528", flat_cells == 528);
  return summary();
}
