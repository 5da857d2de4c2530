// blank::SheetThickness on meshes that are not the structured rectangle
// (doc/theory.md §6, D72). Under an affine map x = F X + b of a flat sheet
// of thickness t0 the top and bottom stay parallel planes at the distance
// t0 / |F^-T e_z| and the surface points map as points: the measurement is
// exact there on any mesh, so the tolerance is round-off (1e-12 relative;
// the errors seen are about 1e-15). Meshes: a two-layer block with some
// cells refined (hanging nodes, three layers under part of the top), the
// extruded disc meshes of Blank outline = circle (quarter and full). The
// rays of the profiles are checked on structured grids, where their
// crossings with the grid lines are known.
#include "test_utilities.h"

#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/blank/blank_geometry.h>
#include <deepdraw/blank/sheet_thickness.h>
#include <random>
#include <string>
#include <vector>

using namespace dealii;
using namespace deepdraw::blank;
using namespace deepdraw_test;

namespace
{
  const Tensor<2, 3>
    F({{1.1, 0.2, 0.05}, {-0.1, 0.9, 0.1}, {0.03, -0.02, 1.3}});
  const Tensor<1, 3> b({0.4, -1.2, 2.5});

  // The affine map of every vertex, and the exact thickness t0 / |F^-T e_z|.
  void
  check_affine(const Triangulation<3> &triangulation,
               const double            t0,
               const std::string      &name)
  {
    std::cout << name << std::endl;
    const std::vector<Point<3>> &X = triangulation.get_vertices();
    std::vector<Point<3>>        x(X.size());
    for (unsigned int v = 0; v < X.size(); ++v)
      x[v] = Point<3>(F * X[v] + b);
    SheetThickness sheet(triangulation, X);
    sheet.update(x);
    const double expected
      = t0 / (invert(transpose(F)) * Tensor<1, 3>({0., 0., 1.})).norm();

    double            worst = 0., worst_mid = 0.;
    unsigned int      located = 0;
    std::vector<bool> used    = triangulation.get_used_vertices();
    for (unsigned int v = 0; v < X.size(); ++v)
      if (used[v])
      {
        const auto location = sheet.locate(Point<2>(X[v][0], X[v][1]));
        if (!location)
          continue;
        ++located;
        worst
          = std::max(worst, std::abs(sheet.thickness(*location, x) - expected));
        const Point<3> mid_reference(X[v][0], X[v][1], 0.5 * t0);
        worst_mid = std::max(worst_mid,
                             (SheetThickness::mid_surface(*location, x)
                              - Point<3>(F * mid_reference + b))
                               .norm());
      }
    // Random points over the sheet.
    std::mt19937                            random(7);
    std::uniform_int_distribution<unsigned> pick(0, X.size() - 1);
    std::uniform_real_distribution<double>  shift(-0.3, 0.3);
    unsigned int                            random_points = 0;
    for (unsigned int k = 0; k < 2000; ++k)
    {
      const unsigned int v = pick(random);
      if (!used[v])
        continue;
      const Point<2> p(X[v][0] + shift(random), X[v][1] + shift(random));
      if (const auto location = sheet.locate(p))
      {
        ++random_points;
        worst
          = std::max(worst, std::abs(sheet.thickness(*location, x) - expected));
      }
    }
    check_true("every used vertex located (" + std::to_string(located) + " of "
                 + std::to_string(triangulation.n_used_vertices()) + ")",
               located == triangulation.n_used_vertices());
    check_true("random points located: " + std::to_string(random_points),
               random_points > 500);
    check_close("largest thickness error", worst, 0., 1e-12 * t0);
    check_close("largest mid-surface error", worst_mid, 0., 1e-12 * 10.);
  }


  void
  check_locally_refined_block()
  {
    Triangulation<3> triangulation;
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {4, 3, 2},
                                              Point<3>(0, 0, 0),
                                              Point<3>(4, 3, 0.8),
                                              /*colorize=*/true);
    // Top-layer cells with x < 2 and one bottom-layer cell elsewhere.
    for (const auto &cell : triangulation.active_cell_iterators())
      if ((cell->center()[2] > 0.4 && cell->center()[0] < 2.)
          || (cell->center()[2] < 0.4 && cell->center()[0] > 3.
              && cell->center()[1] < 1.))
        cell->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();
    check_true("the mesh has hanging nodes", triangulation.has_hanging_nodes());
    check_affine(triangulation, 0.8, "locally refined two-layer block");
  }


  void
  check_disc(const std::string &planes)
  {
    ParameterHandler prm;
    BlankGeometry::declare_parameters(prm);
    prm.enter_subsection("Geometry");
    prm.set("Blank outline", "circle");
    prm.set("Diameter", "60");
    prm.set("Thickness", "1.2");
    prm.set("Elements along radius", "7");
    prm.set("Layers through thickness", "3");
    prm.set("Symmetry planes", planes);
    prm.leave_subsection();
    BlankGeometry geometry;
    geometry.parse_parameters(prm);
    Triangulation<3> triangulation;
    geometry.create_mesh(triangulation);
    check_affine(triangulation,
                 1.2,
                 "extruded disc mesh, symmetry planes '" + planes + "'");
  }


  // Rays on the structured grid nx x ny on [0, L] x [0, W]: the crossings
  // with x = i L/nx and y = j W/ny.
  void
  check_rays(const unsigned int         nx,
             const unsigned int         ny,
             const double               L,
             const double               W,
             const std::vector<double> &diagonal_x0)
  {
    std::cout << "rays on " << nx << " x " << ny << std::endl;
    Triangulation<3> triangulation;
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {nx, ny, 1},
                                              Point<3>(0, 0, 0),
                                              Point<3>(L, W, 0.5),
                                              true);
    const SheetThickness sheet(triangulation, triangulation.get_vertices());
    const std::vector<double> ox = sheet.ray_crossings(Tensor<1, 2>({1., 0.}));
    check_true("OX has nx + 1 points", ox.size() == nx + 1);
    for (unsigned int i = 0; i < std::min<std::size_t>(ox.size(), nx + 1); ++i)
      check_close("OX s", ox[i], i * L / nx, 1e-13);
    const std::vector<double> od
      = sheet.ray_crossings(Tensor<1, 2>({std::sqrt(0.5), std::sqrt(0.5)}));
    check_true("OD has " + std::to_string(diagonal_x0.size()) + " points",
               od.size() == diagonal_x0.size());
    for (unsigned int k = 0; k < std::min(od.size(), diagonal_x0.size()); ++k)
      check_close("OD s", od[k], std::sqrt(2.) * diagonal_x0[k], 1e-13);
  }
} // namespace


int
main()
{
  check_locally_refined_block();
  check_disc("x, y");
  check_disc("");
  check_disc("y");
  check_rays(4, 4, 2., 2., {0., 0.5, 1., 1.5, 2.});
  check_rays(4, 3, 2., 2., {0., 0.5, 2. / 3., 1., 4. / 3., 1.5, 2.});
  check_rays(4, 2, 2., 1., {0., 0.5, 1.});
  check_rays(2, 4, 1., 3., {0., 0.5, 0.75, 1.});
  return summary();
}
