// The Newton system split by rows under mpirun (D214), run on 3 ranks: each
// rank adds its cells (METIS's partition, D215), the rows it holds and does not
// own go to their owners, and the contact pairs are added on every rank alike.
// Checked against the whole system assembled by deal.II on every rank:
// 6 x 6 x 2 hexahedra, x = 0 held by constraints, one pair [u (3),
// lambda (3), z] per top node with pseudo-random local systems (so that
// pairs lie on every rank and on the partition boundaries, and the tool's
// row collects all of them).
// - Each row is owned by exactly one rank, and the owned rows summed over
//   the ranks equal the reference to round-off: the sums of up to 8 cells
//   are added in another order (measured 1.4e-14 on entries up to 145:
//   1e-16 of the largest; allowed 1e-15).
// - The split solve (MUMPS with the rows each rank owns, the tool
//   position bordered; the pseudo-random blocks do not have the
//   structure the condensation needs, so the whole system is solved)
//   equals UMFPACK's solution of the reference (a diagonally dominant,
//   well-conditioned matrix: measured 1.1e-16 of the largest value;
//   allowed 1e-14, other pivot orders).
#include "sheet_with_pairs.h"
#include "test_utilities.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>
#include <deepdraw/linear_algebra/newton_linear_system.h>
#include <deepdraw/parallel/cell_partition.h>
#include <deepdraw/parallel/ranks.h>
#include <iostream>
#include <map>
#include <vector>

using namespace dealii;
using namespace deepdraw_test;

namespace
{
  // A cell's matrix: pseudo-random, diagonally dominant so that the
  // assembled system is regular.
  void
  cell_system(const unsigned int  cell,
              FullMatrix<double> &matrix,
              Vector<double>     &rhs)
  {
    for (unsigned int i = 0; i < matrix.m(); ++i)
    {
      rhs(i) = pseudo_random(1000 * cell + i);
      for (unsigned int j = 0; j < matrix.n(); ++j)
        matrix(i, j) = 0.1 * pseudo_random(1000 * cell + 50 * i + j);
      matrix(i, i) += 5.;
    }
  }

  void
  pair_system(const unsigned int  p,
              FullMatrix<double> &matrix,
              Vector<double>     &rhs)
  {
    for (unsigned int i = 0; i < 7; ++i)
    {
      rhs(i) = pseudo_random(77 * p + i);
      for (unsigned int j = 0; j < 7; ++j)
        matrix(i, j) = 0.2 * pseudo_random(7000 + 77 * p + 7 * i + j);
      matrix(i, i) += 3.;
    }
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               n_ranks = deepdraw::parallel::n_ranks();
  SheetWithPairs                   sheet(6, 6, 2, 1.);
  // The cells divided among the ranks as in a run (METIS, D215).
  deepdraw::parallel::partition_cells(sheet.mesh);
  const std::vector<unsigned int> owners_of_cells
    = deepdraw::parallel::cell_owners(sheet.mesh);
  // METIS cuts the fewest faces: between columns of cells (12 faces per
  // cut line of 6 columns), never between the two layers (36 faces). Every
  // column is on one rank, and the ranks' cells differ by a few at most.
  std::map<std::pair<long, long>, unsigned int> column_owner;
  bool                                          columns_whole = true;
  std::vector<unsigned int>                     cells_of_rank(n_ranks, 0);
  for (const auto &cell : sheet.mesh.active_cell_iterators())
  {
    const Point<3>              centre = cell->center();
    const std::pair<long, long> column{std::lround(centre[0] * 1e6),
                                       std::lround(centre[1] * 1e6)};
    const unsigned int          owner = cell->subdomain_id();
    const auto [entry, added]         = column_owner.emplace(column, owner);
    columns_whole                     = columns_whole && entry->second == owner;
    ++cells_of_rank[owner];
  }
  const auto &dof_handler = sheet.dof_handler;
  const auto &constraints = sheet.constraints;
  const auto &pairs       = sheet.pairs;
  const auto  n           = sheet.n_unknowns;
  const auto  system      = deepdraw::linear_algebra::make_system({});
  system->reinit(sheet.layout());
  system->zero(true);

  // The reference, whole on every rank.
  SparsityPattern pattern;
  sheet.reference_pattern(pattern);
  SparseMatrix<double> reference(pattern);
  Vector<double>       reference_rhs(n);

  // The cells: each rank its own, as the element assembly does; the
  // right-hand side is summed over the ranks as there.
  const unsigned int n_dofs = dof_handler.get_fe().n_dofs_per_cell();
  FullMatrix<double> local(n_dofs, n_dofs);
  Vector<double>     local_rhs(n_dofs);
  std::vector<types::global_dof_index> dofs(n_dofs);
  for (const auto &cell : dof_handler.active_cell_iterators())
  {
    const unsigned int index = cell->active_cell_index();
    cell->get_dof_indices(dofs);
    cell_system(index, local, local_rhs);
    constraints.distribute_local_to_global(local,
                                           local_rhs,
                                           dofs,
                                           reference,
                                           reference_rhs);
    if (deepdraw::parallel::is_owned(*cell))
      system->matrix().add_local(constraints,
                                 local,
                                 local_rhs,
                                 dofs,
                                 system->rhs());
  }
  deepdraw::parallel::sum(system->rhs().begin(), n);
  system->matrix().sum_over_ranks();
  // The pairs on every rank alike.
  FullMatrix<double> pair_matrix(7, 7);
  Vector<double>     pair_rhs(7);
  for (unsigned int p = 0; p < pairs.size(); ++p)
  {
    pair_system(p, pair_matrix, pair_rhs);
    system->matrix().add_local(constraints,
                               pair_matrix,
                               pair_rhs,
                               pairs[p],
                               system->rhs());
    constraints.distribute_local_to_global(pair_matrix,
                                           pair_rhs,
                                           pairs[p],
                                           reference,
                                           reference_rhs);
  }

  // The owned rows, gathered: every row exactly once.
  FullMatrix<double> assembled;
  system->copy_to(assembled);
  std::vector<double> owners(n, 0.);
  for (types::global_dof_index i = 0; i < n; ++i)
    for (types::global_dof_index j = 0; j < n && owners[i] == 0.; ++j)
      owners[i] = assembled(i, j) != 0. ? 1. : 0.;
  deepdraw::parallel::sum(owners.data(), n);
  deepdraw::parallel::sum(&assembled(0, 0), std::size_t(n) * n);
  double difference = 0., largest = 0.;
  for (types::global_dof_index i = 0; i < n; ++i)
    for (types::global_dof_index j = 0; j < n; ++j)
    {
      difference
        = std::max(difference, std::abs(assembled(i, j) - reference.el(i, j)));
      largest = std::max(largest, std::abs(reference.el(i, j)));
    }
  const double fewest_owners = *std::min_element(owners.begin(), owners.end());
  const double most_owners   = *std::max_element(owners.begin(), owners.end());
  Vector<double> rhs_difference(system->rhs());
  rhs_difference -= reference_rhs;

  // The split solve against a whole one.
  Vector<double> solution(n), expected(n);
  system->solve(solution, {n - 1}, {});
  SparseDirectUMFPACK whole;
  whole.initialize(reference);
  whole.vmult(expected, reference_rhs);
  Vector<double> solution_difference(solution);
  solution_difference -= expected;

  if (deepdraw::parallel::is_root())
  {
    std::cout << n_ranks << " ranks, " << n << " unknowns, " << pairs.size()
              << " pairs\n";
    check_true("run on 3 ranks", n_ranks == 3);
    check_true("every column of cells on one rank", columns_whole);
    for (unsigned int r = 0; r < n_ranks; ++r)
      check_close("cells of rank " + std::to_string(r),
                  cells_of_rank[r],
                  72. / n_ranks,
                  2.);
    check_true("each row owned by exactly one rank",
               fewest_owners == 1. && most_owners == 1.);
    check_true("the matrix was filled", largest > 1.);
    check_close("owned rows against deal.II's whole matrix",
                difference,
                0.,
                1e-15 * largest);
    check_close("right-hand side against deal.II's",
                rhs_difference.linfty_norm(),
                0.,
                1e-15 * reference_rhs.linfty_norm());
    check_close("split solve against UMFPACK's",
                solution_difference.linfty_norm(),
                0.,
                1e-14 * expected.linfty_norm());
  }
  return deepdraw::parallel::is_root() ? summary() : 0;
}
