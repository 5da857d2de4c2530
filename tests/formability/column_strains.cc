// The strains of the sheet's columns (postprocess::ColumnStrains,
// doc/theory_formability.md §1.1) are exact for homogeneous deformations on
// any hexahedral sheet mesh: every vertex of a 4 x 3 x 2 plate is mapped by
// x = F X + c with a known F, and every column's bottom, mid and top
// surface must give the principal stretches of F in the plane (ln lambda_1,
// ln lambda_2) and the thickness strain ln lambda_3. F: uniaxial, plane
// strain and equibiaxial stretching, a rigid rotation into a vertical wall
// (zero strains: no coordinate plane is assumed), and a stretch along an
// oblique in-plane direction turned about an oblique axis. Meshes: the
// structured plate, two footprints refined in the plane (whole columns,
// hanging vertices), one bottom cell refined isotropically (a footprint
// split through the thickness: the coarse cell over it belongs to the four
// finer columns, D173), the same in a plate of three layers with the middle
// cell refined (coarse cells above and below) and with the bottom and the
// top cell refined (finer stacks over the same footprints, one column
// each), and the plate with its interior vertices distorted. Also: every
// cell has a column, whose centre lies on the cell's footprint; no two
// columns share a centre; the column counts of the refined meshes, and each
// refined column continues the column its cells came from
// (inherited_from). Measured 2.8e-15 at most (round-off): 1e-14 allowed.
#include "../test_utilities.h"

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/postprocess/column_strains.h>
#include <set>

using namespace deepdraw;
using namespace dealii;

namespace
{
  constexpr double tolerance = 1e-14;

  // Rotation by angle about the unit axis (Rodrigues).
  Tensor<2, 3>
  rotation(const Tensor<1, 3> &axis, const double angle)
  {
    const Tensor<1, 3> n = axis / axis.norm();
    Tensor<2, 3>       R;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        R[i][j]
          = std::cos(angle) * (i == j) + (1. - std::cos(angle)) * n[i] * n[j];
    const Tensor<2, 3> W(
      {{0., -n[2], n[1]}, {n[2], 0., -n[0]}, {-n[1], n[0], 0.}});
    return R + std::sin(angle) * W;
  }

  Tensor<2, 3>
  stretch(const double l1, const double l2, const double l3)
  {
    Tensor<2, 3> F;
    F[0][0] = l1;
    F[1][1] = l2;
    F[2][2] = l3;
    return F;
  }

  struct Case
  {
    std::string  name;
    Tensor<2, 3> F;
    // ln of the in-plane principal stretches and of the thickness stretch.
    double major, minor, thickness;
  };

  std::vector<Case>
  cases()
  {
    // In-plane stretches along a direction 30 degrees from x, then the
    // sheet turned by 70 degrees about an oblique axis.
    const Tensor<2, 3> Q = rotation(Tensor<1, 3>({0., 0., 1.}), M_PI / 6.);
    const Tensor<2, 3> oblique
      = rotation(Tensor<1, 3>({1., 2., 3.}), 70. * M_PI / 180.) * Q
        * stretch(std::exp(0.25), std::exp(-0.05), std::exp(-0.2))
        * transpose(Q);
    return {{"uniaxial",
             stretch(std::exp(0.2), std::exp(-0.1), std::exp(-0.1)),
             0.2,
             -0.1,
             -0.1},
            {"plane strain",
             stretch(std::exp(0.3), 1., std::exp(-0.3)),
             0.3,
             0.,
             -0.3},
            {"equibiaxial",
             stretch(std::exp(0.15), std::exp(0.15), std::exp(-0.3)),
             0.15,
             0.15,
             -0.3},
            {"rigid rotation into a wall",
             rotation(Tensor<1, 3>({0., 1., 0.}), M_PI / 2.),
             0.,
             0.,
             0.},
            {"oblique stretch, turned", oblique, 0.25, -0.05, -0.2}};
  }

  // The largest error of any column and surface under every case; returns
  // the columns of the mesh.
  postprocess::ColumnStrains
  check_mesh(const std::string &mesh_name, const Triangulation<3> &mesh)
  {
    const std::vector<Point<3>> &X = mesh.get_vertices();
    blank::SheetThickness        surfaces(mesh, X);
    postprocess::ColumnStrains   columns;
    columns.set_up(mesh, X, surfaces);
    bool every_cell = true;
    for (const auto &cell : mesh.active_cell_iterators())
    {
      const unsigned int column
        = columns.column_of_cell()[cell->active_cell_index()];
      if (column >= columns.n_columns())
      {
        every_cell = false;
        continue;
      }
      const Point<2> &centre = columns.centre(column);
      // The cell's footprint: its bounding box in x, y.
      const BoundingBox<3> box = cell->bounding_box();
      for (unsigned int d = 0; d < 2; ++d)
        every_cell = every_cell && centre[d] >= box.lower_bound(d) - 1e-12
                     && centre[d] <= box.upper_bound(d) + 1e-12;
    }
    deepdraw_test::check_true(mesh_name
                                + ": every cell in a column on its footprint",
                              every_cell);
    std::set<std::pair<double, double>> centres;
    for (unsigned int k = 0; k < columns.n_columns(); ++k)
      centres.emplace(columns.centre(k)[0], columns.centre(k)[1]);
    deepdraw_test::check_true(mesh_name + ": no two columns at one centre",
                              centres.size() == columns.n_columns());

    const Tensor<1, 3> shift({3., -2., 7.});
    for (const Case &c : cases())
    {
      std::vector<Point<3>> x(X.size());
      for (unsigned int v = 0; v < X.size(); ++v)
        x[v] = Point<3>(c.F * X[v] + shift);
      surfaces.update(x);
      double error = 0.;
      for (const postprocess::ColumnStrain &column :
           columns.compute(x, surfaces, 0.5))
      {
        for (const formability::SurfaceStrain &s : column.surfaces)
          error = std::max({error,
                            std::abs(s.major_strain - c.major),
                            std::abs(s.minor_strain - c.minor)});
        error
          = std::max(error, std::abs(column.thickness_strain - c.thickness));
      }
      deepdraw_test::check_close(mesh_name + ", " + c.name
                                   + ": largest error of eps1, eps2, eps3",
                                 error,
                                 0.,
                                 tolerance);
    }
    return columns;
  }

  void
  make_plate(Triangulation<3> &mesh, const unsigned int layers = 2)
  {
    GridGenerator::subdivided_hyper_rectangle(mesh,
                                              {4, 3, layers},
                                              Point<3>(0., 0., 0.),
                                              Point<3>(4., 3., 0.5),
                                              /*colorize=*/true);
  }
} // namespace


int
main()
{
  Triangulation<3> plate;
  make_plate(plate);
  const postprocess::ColumnStrains coarse
    = check_mesh("structured plate", plate);
  deepdraw_test::check_true("structured plate: 12 columns",
                            coarse.n_columns() == 12);

  // Two footprints (x < 2, y < 1) refined in the plane, both layers.
  Triangulation<3> in_plane;
  make_plate(in_plane);
  for (const auto &cell : in_plane.active_cell_iterators())
    if (cell->center()[0] < 2. && cell->center()[1] < 1.)
      cell->set_refine_flag(RefinementCase<3>::cut_xy);
  in_plane.execute_coarsening_and_refinement();
  const postprocess::ColumnStrains refined
    = check_mesh("refined in the plane", in_plane);
  deepdraw_test::check_true("refined in the plane: 12 - 2 + 8 columns",
                            refined.n_columns() == 18);
  // The coarse plate's columns are numbered by their unit squares; each
  // refined column must come from the square that holds its centre.
  const std::vector<unsigned int> parents   = refined.inherited_from(coarse);
  bool                            inherited = true;
  for (unsigned int k = 0; k < refined.n_columns(); ++k)
  {
    if (parents[k] >= coarse.n_columns())
    {
      inherited = false;
      continue;
    }
    const Point<2> &centre = refined.centre(k);
    const Point<2> &parent = coarse.centre(parents[k]);
    inherited = inherited && std::floor(centre[0]) == std::floor(parent[0])
                && std::floor(centre[1]) == std::floor(parent[1]);
  }
  deepdraw_test::check_true("each refined column comes from its coarse one",
                            inherited);

  // One bottom cell refined in all directions.
  Triangulation<3> isotropic;
  make_plate(isotropic);
  isotropic.begin_active()->set_refine_flag();
  isotropic.execute_coarsening_and_refinement();
  deepdraw_test::check_true(
    "one cell refined isotropically: 12 - 1 + 4 columns",
    check_mesh("one cell refined isotropically", isotropic).n_columns() == 15);

  // Three layers: the middle cell of the first footprint refined (a coarse
  // cell below and above it), and the bottom and top cells refined (the
  // finer stacks over the same four footprints).
  for (const std::vector<unsigned int> &refined_layers :
       std::vector<std::vector<unsigned int>>{{1}, {0, 2}})
  {
    Triangulation<3> layered;
    make_plate(layered, 3);
    for (const auto &cell : layered.active_cell_iterators())
      for (const unsigned int layer : refined_layers)
        if (cell->center()[0] < 1. && cell->center()[1] < 1.
            && std::abs(cell->center()[2] - (layer + 0.5) / 6.) < 1e-9)
          cell->set_refine_flag();
    layered.execute_coarsening_and_refinement();
    const std::string name = "three layers, layer(s) "
                             + std::to_string(refined_layers.front())
                             + (refined_layers.size() > 1 ? " and 2" : "")
                             + " of a footprint refined";
    deepdraw_test::check_true(name + ": 12 - 1 + 4 columns",
                              check_mesh(name, layered).n_columns() == 15);
  }

  // Interior vertices moved at random (the surfaces stay where they were).
  Triangulation<3> distorted;
  make_plate(distorted);
  GridTools::distort_random(0.3, distorted, /*keep_boundary=*/true);
  check_mesh("distorted interior", distorted);
  return deepdraw_test::summary();
}
