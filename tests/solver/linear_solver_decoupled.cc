// LinearSolver with decoupled unknowns (D60): unknowns whose row and column
// hold only the diagonal (open contact pairs, constrained dofs) are left out
// of the factorisation and solved as rhs_i / A_ii. Checked on a
// contact-like saddle-point matrix (tests/contact/
// linear_solver_changing_values has the same shape), with and without a
// bordered unknown, over a sequence of open/closed states:
// - the solution solves the system to a relative residual of 1e-12 and
//   equals the full system's to 1e-9;
// - the factorised matrix has the size of the kept unknowns;
// - the reduced pattern is kept while the unknowns left out stay decoupled
//   (no new reduction for a state with more pairs open), rebuilt when one
//   closes or after reset_reduction();
// - an unknown listed as decoupled that is not (a closed pair) is kept: the
//   solution is still exact.
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
  std::vector<types::global_dof_index>
  open_unknowns(const std::vector<bool> &closed)
  {
    const unsigned int                   n = closed.size();
    std::vector<types::global_dof_index> unknowns{0};
    for (unsigned int i = 0; i < n; ++i)
      if (!closed[i])
        unknowns.push_back(n + i);
    return unknowns;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               n = 30;
  SparsityPattern                  pattern;
  make_contact_like_pattern(n, pattern);
  SparseMatrix<double> A(pattern);

  Vector<double> b(2 * n + 1);
  for (unsigned int i = 0; i < b.size(); ++i)
    b[i] = 1. + std::sin(1. + i);

  // States: every third closed; more open (a subset of the first's closed
  // set stays closed); one more closed; all closed but one.
  std::vector<std::vector<bool>> states(4, std::vector<bool>(n, false));
  for (unsigned int i = 0; i < n; ++i)
  {
    states[0][i] = i % 3 == 0;
    states[1][i] = i % 6 == 0;
    states[2][i] = i % 6 == 0 || i == 5;
    states[3][i] = i != 7;
  }
  // Node 0 is the constrained dof: its multiplier is never closed.
  for (auto &state : states)
    state[0] = false;
  // Reductions expected after each state: the first builds one; the
  // second keeps it (what it leaves out is still decoupled, and 5 of the
  // 38 it keeps (39 without the border) became decoupled, fewer than a
  // quarter); the
  // third closes pair 5, which was left out: rebuilt; the fourth closes
  // most: rebuilt.
  const std::vector<unsigned int> expected_reductions = {1, 1, 2, 3};

  for (const bool bordered : {false, true})
  {
    const std::vector<types::global_dof_index> border
      = bordered ? std::vector<types::global_dof_index>{2 * n}
                 : std::vector<types::global_dof_index>{};
    const std::string name = bordered ? "bordered" : "not bordered";
    deepdraw::solver::LinearSolverParameters parameters;
    deepdraw::solver::LinearSolver reduced(parameters), full(parameters);
    for (unsigned int k = 0; k < states.size(); ++k)
    {
      fill_contact_like_matrix(A, states[k]);
      const auto     decoupled = open_unknowns(states[k]);
      Vector<double> x, x_full, r(b.size());
      reduced.solve(A, b, x, border, decoupled);
      full.solve(A, b, x_full, border);
      A.vmult(r, x);
      r -= b;
      const std::string system    = name + ", system " + std::to_string(k);
      const double      tolerance = 1e-12;
      check_close(system + ": relative residual",
                  r.l2_norm() / b.l2_norm(),
                  0.,
                  tolerance);
      x_full -= x;
      check_close(system + ": difference to the full solve",
                  x_full.l2_norm() / x.l2_norm(),
                  0.,
                  1e-9);
      const auto &statistics = reduced.statistics();
      check_close(system + ": reductions",
                  statistics.reductions,
                  expected_reductions[k],
                  0.);
    }
    // The last state: all pairs closed but 0 and 7, so the constrained
    // displacement and these two multipliers are left out (and the
    // bordered unknown).
    check_close(name + ": factorised unknowns",
                reduced.statistics().factorized_unknowns,
                2 * n + 1 - 3 - border.size(),
                0.);

    // After reset_reduction() the next solve leaves out exactly what it is
    // given (the state with more pairs open is not reused).
    reduced.reset_reduction();
    fill_contact_like_matrix(A, states[1]);
    Vector<double> x;
    reduced.solve(A, b, x, border, open_unknowns(states[1]));
    check_close(name + ": factorised unknowns after a reset",
                reduced.statistics().factorized_unknowns,
                2 * n + 1 - open_unknowns(states[1]).size() - border.size(),
                0.);

    // A closed multiplier listed as decoupled is kept: still exact.
    fill_contact_like_matrix(A, states[0]);
    auto wrong = open_unknowns(states[0]);
    wrong.push_back(n + 3);
    reduced.solve(A, b, x, border, wrong);
    Vector<double> r(b.size());
    A.vmult(r, x);
    r -= b;
    check_close(name + ": relative residual with a coupled unknown listed",
                r.l2_norm() / b.l2_norm(),
                0.,
                1e-12);
  }
  return summary();
}
