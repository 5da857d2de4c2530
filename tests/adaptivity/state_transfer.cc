// adaptivity::refine_and_transfer (doc/theory.md §8, D57) on a 2 x 1 x 1 block
// of Q1 hexahedra carrying a homogeneous state (stress, back stress, epbar,
// rotated material axes) plus a linear field of epbar, and the linear
// displacement u = A X + b:
// - global isotropic refinement, then one cell refined isotropically
//   (hanging nodes), then one cell cut in z only (the through-thickness
//   refinement);
// - the constant fields are exact (difference 0), rotations orthogonal to
//   round-off, u = A X + b at every vertex to 1e-14 (Q1 interpolation of a
//   linear field), the linear epbar field off by exactly the largest
//   distance from a child point to its nearest parent Gauss point,
//   (3/(4 sqrt 3) - 1/4) h = 0.183 h along a halved direction of size h
//   (the O(h) error of the transfer, doc/theory.md §8), enhanced
//   parameters kept on unrefined cells and zero on children;
// - with 3 Gauss points through the thickness (D202), a cut in z: a field
//   linear in z is carried exactly by the interpolated transfer (piecewise
//   linear between the parent's points) and, by the nearest point, with the
//   largest offset of a child point from its nearest parent point.
#include "adaptivity/transfer_block.h"
#include "test_utilities.h"

#include <algorithm>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/adaptivity/state_transfer.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/material/elasto_plasticity.h>
#include <limits>

using namespace dealii;
using namespace deepdraw;

namespace
{
  Tensor<1, 3>
  linear_displacement(const Point<3> &X)
  {
    return Tensor<1, 3>({0.01 * X[0] + 0.002 * X[2] + 0.1,
                         -0.003 * X[1] + 0.004 * X[0],
                         0.005 * X[2] - 0.001 * X[1] - 0.2});
  }

  // Rotation by 0.3 rad about (1, 1, 1)/sqrt 3 (Rodrigues).
  Tensor<2, 3>
  rotation()
  {
    const double       angle = 0.3;
    const Tensor<1, 3> axis(
      {1. / std::sqrt(3.), 1. / std::sqrt(3.), 1. / std::sqrt(3.)});
    Tensor<2, 3> W;
    W[0][1] = -axis[2], W[0][2] = axis[1], W[1][0] = axis[2];
    W[1][2] = -axis[0], W[2][0] = -axis[1], W[2][1] = axis[0];
    return unit_symmetric_tensor<3>() + std::sin(angle) * W
           + (1. - std::cos(angle)) * W * W;
  }

  using Block = deepdraw_test::TransferBlock;

  // Quadrature point positions in real space, by active cell.
  std::vector<Point<3>>
  point_positions(const Triangulation<3> &triangulation,
                  const unsigned int      points_through_thickness = 2)
  {
    const Quadrature<3> quadrature
      = fe::selective_reduced_quadrature(points_through_thickness);
    const MappingQ1<3>    mapping;
    std::vector<Point<3>> points;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (unsigned int q = 0; q < fe::n_weighted_points(quadrature); ++q)
        points.push_back(
          mapping.transform_unit_to_real_cell(cell, quadrature.point(q)));
    return points;
  }

  void
  set_up(Block &block)
  {
    GridGenerator::subdivided_hyper_rectangle(block.triangulation,
                                              {2, 1, 1},
                                              Point<3>(0., 0., 0.),
                                              Point<3>(6., 3., 1.));
    block.set_total_displacement([](const Point<3> &x, unsigned int)
                                 { return linear_displacement(x); });
    auto &state              = block.state;
    state.converged_solution = state.total_displacement;
    // A contact block that the transfer must drop.
    state.converged_solution.grow_or_shrink(block.dof_handler.n_dofs() + 6);
    state.previous_converged_solution = state.converged_solution;

    fe::QuadraturePointHistory point;
    point.state.stress = SymmetricTensor<2, 3>({200., -50., 10., 5., -3., 7.});
    point.state.back_stress
      = SymmetricTensor<2, 3>({12., -6., -6., 1., 0., 2.});
    point.material_axes = rotation();
    state.history.assign(8 * block.triangulation.n_active_cells(), point);
    state.enhanced_parameters.resize(block.triangulation.n_active_cells());
    for (auto &cell : state.enhanced_parameters)
      cell.values.fill(0.25);
  }

  // epbar = 0.01 x at every point: the linear field each refinement is
  // measured against.
  void
  set_linear_field(Block &block)
  {
    const auto positions = point_positions(block.triangulation);
    for (unsigned int q = 0; q < positions.size(); ++q)
      block.state.history[q].state.equivalent_plastic_strain
        = 0.01 * positions[q][0];
  }

  // Checks the transferred state after one refinement.
  void
  check(const Block &block, const std::string &label, const double h_parent)
  {
    const auto &state = block.state;
    deepdraw_test::check_true(
      label + ": sizes",
      state.history.size() == 8 * block.triangulation.n_active_cells()
        && state.total_displacement.size() == block.dof_handler.n_dofs()
        && state.converged_solution.size() == block.dof_handler.n_dofs());
    double      constant_error = 0., orthogonality = 0., field_error = 0.;
    const auto &reference = state.history.front();
    const auto  positions = point_positions(block.triangulation);
    for (unsigned int q = 0; q < state.history.size(); ++q)
    {
      const auto &point = state.history[q];
      constant_error    = std::max(
        {constant_error,
            (point.state.stress - reference.state.stress).norm(),
            (point.state.back_stress - reference.state.back_stress).norm(),
            (point.material_axes - reference.material_axes).norm()});
      orthogonality
        = std::max(orthogonality,
                   (transpose(point.material_axes) * point.material_axes
                    - unit_symmetric_tensor<3>())
                     .norm());
      field_error = std::max(field_error,
                             std::abs(point.state.equivalent_plastic_strain
                                      - 0.01 * positions[q][0]));
    }
    deepdraw_test::check_close(label + ": constant stress, back stress, axes",
                               constant_error,
                               0.,
                               0.);
    deepdraw_test::check_close(label + ": R^T R - I", orthogonality, 0., 1e-15);
    // Nearest parent point: in each halved direction the child's points
    // sit at 1/4 -+ 1/(4 sqrt 3) of the parent, its nearest Gauss point at
    // 1/2 - 1/(2 sqrt 3): the largest offset is (3/(4 sqrt 3) - 1/4) h.
    deepdraw_test::check_close(label
                                 + ": linear epbar, largest error (mm of x)",
                               field_error / 0.01,
                               (0.75 / std::sqrt(3.) - 0.25) * h_parent,
                               1e-12);

    double u_error = 0.;
    for (const auto &cell : block.dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        for (unsigned int c = 0; c < 3; ++c)
          u_error
            = std::max(u_error,
                       std::abs(
                         state.total_displacement[cell->vertex_dof_index(v, c)]
                         - linear_displacement(cell->vertex(v))[c]));
    deepdraw_test::check_close(label + ": u = A X + b at every vertex",
                               u_error,
                               0.,
                               1e-14);
  }

  // epbar = 0.01 z on a 1 x 1 x 1 cell with 3 points through the
  // thickness, cut in z once, by the given rule; returns the largest error
  // in mm of z.
  double
  transfer_linear_in_z(const adaptivity::HistoryTransfer rule,
                       const material::ElastoPlasticity &material)
  {
    Block block;
    GridGenerator::hyper_cube(block.triangulation, 0., 1.);
    block.dof_handler.distribute_dofs(block.fe);
    block.state.total_displacement.reinit(block.dof_handler.n_dofs());
    block.state.converged_solution          = block.state.total_displacement;
    block.state.previous_converged_solution = block.state.total_displacement;
    fe::QuadraturePointHistory point;
    point.material_axes = unit_symmetric_tensor<3>();
    for (const Point<3> &x : point_positions(block.triangulation, 3))
    {
      point.state.equivalent_plastic_strain = 0.01 * x[2];
      block.state.history.push_back(point);
    }
    block.triangulation.begin_active()->set_refine_flag(
      RefinementCase<3>::cut_z);
    adaptivity::TransferOptions options;
    options.history  = rule;
    options.material = &material;
    adaptivity::refine_and_transfer(block.triangulation,
                                    block.dof_handler,
                                    block.state,
                                    options);
    const auto positions = point_positions(block.triangulation, 3);
    double     error     = positions.size() == block.state.history.size()
                             ? 0.
                             : std::numeric_limits<double>::infinity();
    for (unsigned int q = 0; q < positions.size() && std::isfinite(error); ++q)
      error = std::max(error,
                       std::abs(
                         block.state.history[q].state.equivalent_plastic_strain
                         - 0.01 * positions[q][2])
                         / 0.01);
    return error;
  }

  void
  check_three_points_through_thickness()
  {
    const material::ElastoPlasticity material{material::MaterialParameters()};
    deepdraw_test::check_close(
      "3 points through the thickness, cut_z, interpolated: linear epbar "
      "exact (mm of z)",
      transfer_linear_in_z(adaptivity::HistoryTransfer::interpolated, material),
      0.,
      1e-15);
    // Gauss points of 3 at 1/2 and 1/2 -+ sqrt(3/5)/2; the lower child's at
    // 1/4 and 1/4 -+ sqrt(3/5)/4 of the parent. The largest offset from a
    // child point to its nearest parent point: the child's middle point
    // (1/4) from the parent's lowest, 1/2 - sqrt(3/5)/2 - 1/4.
    const double r         = std::sqrt(0.6) / 2.;
    const double offsets[] = {std::abs(0.25 - r / 2. - (0.5 - r)),
                              std::abs(0.25 - (0.5 - r)),
                              std::min(std::abs(0.25 + r / 2. - (0.5 - r)),
                                       std::abs(0.25 + r / 2. - 0.5))};
    deepdraw_test::check_close(
      "3 points through the thickness, cut_z, nearest point: largest offset "
      "(mm of z)",
      transfer_linear_in_z(adaptivity::HistoryTransfer::nearest, material),
      *std::max_element(std::begin(offsets), std::end(offsets)),
      1e-14);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Block                            block;
  set_up(block);

  set_linear_field(block);
  block.triangulation.set_all_refine_flags();
  adaptivity::refine_and_transfer(block.triangulation,
                                  block.dof_handler,
                                  block.state);
  check(block, "global refinement", 3.);
  bool children_zero = true;
  for (const auto &cell : block.state.enhanced_parameters)
    children_zero = children_zero && cell.values[0] == 0.;
  deepdraw_test::check_true("children's enhanced parameters are zero",
                            children_zero);
  for (auto &cell : block.state.enhanced_parameters)
    cell.values.fill(0.5);

  // One cell refined: hanging nodes on its faces.
  set_linear_field(block);
  block.triangulation.begin_active()->set_refine_flag();
  adaptivity::refine_and_transfer(block.triangulation,
                                  block.dof_handler,
                                  block.state);
  check(block, "local refinement", 1.5);
  unsigned int kept = 0;
  for (const auto &cell : block.state.enhanced_parameters)
    kept += cell.values[0] == 0.5 ? 1 : 0;
  deepdraw_test::check_true("15 unrefined cells keep their enhanced "
                            "parameters ("
                              + std::to_string(kept) + ")",
                            kept == 15);

  // Cut in z only: the history is transferred by the same rule.
  // A 3 x 1.5 x 0.5 cell of the first refinement away from the refined
  // one (all its neighbours unrefined, so that no further refinement is
  // forced); its x spacing does not change, so the nearest-point error in
  // x is zero there.
  set_linear_field(block);
  const unsigned int n_before = block.triangulation.n_active_cells();
  for (const auto &cell : block.triangulation.active_cell_iterators())
  {
    bool isolated = cell->level() == 1;
    for (const unsigned int f : cell->face_indices())
      if (!cell->at_boundary(f))
        isolated = isolated && cell->neighbor(f)->is_active()
                   && cell->neighbor(f)->level() == 1;
    if (isolated)
    {
      cell->set_refine_flag(RefinementCase<3>::cut_z);
      break;
    }
  }
  adaptivity::refine_and_transfer(block.triangulation,
                                  block.dof_handler,
                                  block.state);
  deepdraw_test::check_true(
    "cut_z: one cell more (" + std::to_string(n_before) + " -> "
      + std::to_string(block.triangulation.n_active_cells()) + ")",
    block.triangulation.n_active_cells() == n_before + 1);
  check(block, "cut_z refinement", 0.);
  check_three_points_through_thickness();
  return deepdraw_test::summary();
}
