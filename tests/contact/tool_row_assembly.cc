// The contact pairs of a force-controlled tool add to the tool's row, which
// holds an entry for every pair of the tool. The serial Newton system adds
// a local system without constrained dofs by a binary search in each row
// instead of deal.II's walk from the row's start (D211). Checked against
// AffineConstraints::distribute_local_to_global into a matrix of the same
// pattern: 4 x 4 x 1 hexahedra, one pair [u (3), lambda (3), z] per top
// node with pseudo-random local systems, x = 0 held by constraints so
// that both paths are taken. Both add the same values in the same order,
// so matrix and right-hand side must agree exactly.
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
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>
#include <deepdraw/linear_algebra/newton_linear_system.h>
#include <iostream>
#include <vector>

using namespace dealii;
using namespace deepdraw_test;

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const SheetWithPairs             sheet(4, 4, 1, 1.);
  const auto                      &constraints = sheet.constraints;
  const auto                      &pairs       = sheet.pairs;
  const types::global_dof_index    n           = sheet.n_unknowns;
  const auto system = deepdraw::linear_algebra::make_serial_system({});
  system->reinit(sheet.layout());
  system->zero(true);

  // The reference: the same pattern, filled by deal.II.
  SparsityPattern pattern;
  sheet.reference_pattern(pattern);
  SparseMatrix<double> reference(pattern);
  Vector<double>       reference_rhs(n);

  unsigned int       k = 0, constrained_pairs = 0;
  FullMatrix<double> local(7, 7);
  Vector<double>     local_rhs(7);
  for (const auto &dofs : pairs)
  {
    for (unsigned int i = 0; i < 7; ++i)
    {
      local_rhs(i) = pseudo_random(k++);
      for (unsigned int j = 0; j < 7; ++j)
        // Some zeros, as an open pair's rows have.
        local(i, j) = (i + 2 * j) % 5 == 3 ? 0. : pseudo_random(k++);
    }
    constrained_pairs += constraints.is_constrained(dofs[0]);
    system->matrix().add_local(constraints,
                               local,
                               local_rhs,
                               dofs,
                               system->rhs());
    constraints.distribute_local_to_global(local,
                                           local_rhs,
                                           dofs,
                                           reference,
                                           reference_rhs);
  }

  FullMatrix<double> assembled;
  system->copy_to(assembled);
  double matrix_difference = 0., largest = 0.;
  for (types::global_dof_index i = 0; i < n; ++i)
    for (types::global_dof_index j = 0; j < n; ++j)
    {
      matrix_difference
        = std::max(matrix_difference,
                   std::abs(assembled(i, j) - reference.el(i, j)));
      largest = std::max(largest, std::abs(reference.el(i, j)));
    }
  Vector<double> rhs_difference(system->rhs());
  rhs_difference -= reference_rhs;
  unsigned int tool_row_entries = 0;
  for (types::global_dof_index j = 0; j < n; ++j)
    tool_row_entries += reference.el(n - 1, j) != 0.;

  std::cout << pairs.size() << " pairs (" << constrained_pairs
            << " with a constrained dof), " << tool_row_entries
            << " entries in the tool's row; largest difference "
            << matrix_difference << " (matrix, largest entry " << largest
            << "), " << rhs_difference.linfty_norm() << " (rhs)\n";
  check_true("25 top nodes", pairs.size() == 25);
  check_true("both paths taken: 5 pairs on x = 0", constrained_pairs == 5);
  // Each pair's u and lambda columns but the local zero (5 of 6), less
  // the constrained x = 0 columns of 5 pairs: 120 of at most 151.
  check_true("the tool's row couples every pair", tool_row_entries == 120);
  check_true("the matrix was filled", largest > 0.5);
  check_close("matrix against deal.II's", matrix_difference, 0., 0.);
  check_close("rhs against deal.II's", rhs_difference.linfty_norm(), 0., 0.);
  return summary();
}
