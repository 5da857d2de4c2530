// The Newton matrices of a contact run share one sparsity pattern while the
// values change: entries of open pairs are exactly zero in one iteration and
// nonzero in the next (and a bordered tool-position unknown is eliminated by
// a Schur complement). Every direct solver must then solve each system to
// round-off: a copy that kept the first matrix's nonzero structure (the
// Amesos path did, before D31) solved the second system with a residual of
// 0.08 and the square cup stalled. Checked: ||A x - b|| / ||b|| <= 1e-9 for
// UMFPACK, MUMPS and KLU, with and without a bordered unknown, on a
// saddle-point matrix like the contact block (zero diagonal in stick rows).
#include "contact_like_pattern.h"
#include "test_utilities.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/solver/linear_solver.h>
#include <string>
#include <vector>

using namespace dealii;
using namespace deepdraw_test;

namespace
{
  // n displacement-like unknowns (a 1D chain, tridiagonal stiffness), then a
  // multiplier per node coupled to its node, then one bordered unknown
  // coupled to all multipliers. `closed[i]`: multiplier i is a constraint
  // (zero diagonal, coupling 1) or open (diagonal 1/r, no coupling).
  void
  fill(SparseMatrix<double> &A, const std::vector<bool> &closed)
  {
    const unsigned int n = closed.size();
    A                    = 0.;
    for (unsigned int i = 0; i < n; ++i)
    {
      A.set(i, i, 2. + 0.1 * i);
      if (i > 0)
        A.set(i, i - 1, -1.);
      if (i + 1 < n)
        A.set(i, i + 1, -1.);
      const double coupling = closed[i] ? 1. : 0.;
      A.set(i, n + i, -coupling);
      A.set(n + i, i, coupling);
      A.set(n + i, n + i, closed[i] ? 0. : 1e-3);
      A.set(n + i, 2 * n, closed[i] ? 0.5 : 0.);
      A.set(2 * n, n + i, closed[i] ? 1. : 0.);
    }
    A.set(2 * n, 2 * n, 1.);
  }
} // namespace

int
main(int argc, char *argv[])
{
  // Trilinos (MUMPS, KLU) needs MPI.
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               n = 40;
  SparsityPattern                  pattern;
  make_contact_like_pattern(n, pattern);
  SparseMatrix<double> A(pattern);

  Vector<double> b(2 * n + 1);
  for (unsigned int i = 0; i < b.size(); ++i)
    b[i] = 1. + std::sin(1. + i);

  // Three "iterations": all open, every third closed, all but one closed.
  std::vector<std::vector<bool>> states(3, std::vector<bool>(n, false));
  for (unsigned int i = 0; i < n; ++i)
  {
    states[1][i] = i % 3 == 0;
    states[2][i] = i != 7;
  }

  for (const std::string type : {"UMFPACK", "MUMPS", "KLU"})
    for (const bool bordered : {false, true})
    {
      deepdraw::solver::LinearSolverParameters parameters;
      parameters.type = type;
      deepdraw::solver::LinearSolver solver(parameters);
      for (unsigned int k = 0; k < states.size(); ++k)
      {
        fill(A, states[k]);
        Vector<double> x, r(b.size());
        solver.solve(A,
                     b,
                     x,
                     bordered ? std::vector<types::global_dof_index>{2 * n}
                              : std::vector<types::global_dof_index>{});
        A.vmult(r, x);
        r -= b;
        check_close(type + (bordered ? " bordered" : "") + ", system "
                      + std::to_string(k) + ": relative residual",
                    r.l2_norm() / b.l2_norm(),
                    0.,
                    1e-9);
      }
    }
  return summary();
}
