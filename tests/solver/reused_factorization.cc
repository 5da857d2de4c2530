// LinearSolver with `Reuse factorisation` (D185): after the first solve of
// an increment, a system is solved by right-preconditioned GMRES with the
// kept factors of the last factorised matrix, to the forcing term, and
// factorised afresh when GMRES does not get there. Checked on the
// contact-like saddle-point matrix of linear_solver_decoupled (a chain of
// displacements, a multiplier per node, a bordered "holder" unknown), with
// and without the bordered unknown and the decoupled ones left out:
// - the first solve factorises and is exact (relative residual 1e-12);
// - a slightly changed matrix (values scaled by up to 2 %) is solved with
//   the kept factors: no new factorisation, and the true residual
//   |b - A x| is within the forcing term 0.1 of |b| (the Eisenstat-Walker
//   term is 0.9 (|b_k| / |b_k-1|)^2 = 0.9 here, capped at 0.1);
// - a forcing term GMRES cannot reach in its 2 iterations (1e-12 on a
//   matrix changed by 20 %) falls back to a factorisation, whose solution
//   is exact again;
// - after reset_reduction() (an increment's start) the first solve
//   factorises without trying GMRES;
// - the GMRES budget of `Reuse iterations = auto` (D228).
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
  // The contact-like matrix with every third pair closed (not node 0's),
  // its values scaled by 1 + change * sin(entry number).
  void
  fill(SparseMatrix<double> &A, const double change)
  {
    const unsigned int n = (A.m() - 1) / 2;
    std::vector<bool>  closed(n);
    for (unsigned int i = 0; i < n; ++i)
      closed[i] = i % 3 == 0 && i > 0;
    fill_contact_like_matrix(A, closed);
    unsigned int k = 0;
    for (auto entry = A.begin(); entry != A.end(); ++entry, ++k)
      entry->value() *= 1. + change * std::sin(1. + k);
  }

  double
  relative_residual(const SparseMatrix<double> &A,
                    const Vector<double>       &x,
                    const Vector<double>       &b)
  {
    Vector<double> r(b.size());
    return A.residual(r, x, b) / b.l2_norm();
  }

  // Reuse iterations = auto (D228): max(10, 10 (n / 23 409)^0.4), worked
  // out by hand for the square cup's sheets (3 nodes through the
  // thickness, 3 unknowns a node): 50 x 50 x 2 has 23 409 unknowns,
  // 100 x 100 x 2 91 809 (17.27), 150 x 150 x 2 205 209 (23.83),
  // 300 x 300 x 2 815 409 (41.38). A number given is kept at every size.
  void
  check_budget_rule()
  {
    deepdraw::solver::LinearSolverParameters                automatic;
    const std::vector<std::pair<std::size_t, unsigned int>> expected
      = {{6, 10},
         {6084, 10},
         {23409, 10},
         {91809, 17},
         {205209, 24},
         {815409, 41}};
    for (const auto &[n, budget] : expected)
      check_close("auto budget at " + std::to_string(n) + " unknowns",
                  automatic.gmres_budget(n),
                  budget,
                  0);
    deepdraw::solver::LinearSolverParameters given;
    given.reuse_iterations = 10;
    check_close("given budget at 815 409 unknowns",
                given.gmres_budget(815409),
                10,
                0);
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
  Vector<double>       b(2 * n + 1), x;
  for (unsigned int i = 0; i < b.size(); ++i)
    b[i] = 1. + std::sin(1. + i);

  for (const bool bordered : {false, true})
  {
    const std::vector<types::global_dof_index> border
      = bordered ? std::vector<types::global_dof_index>{2 * n}
                 : std::vector<types::global_dof_index>{};
    // The open pairs' multipliers and the constrained node 0.
    std::vector<types::global_dof_index> decoupled;
    if (bordered)
      for (unsigned int i = 0; i < n; ++i)
        if (i % 3 != 0 || i == 0)
          decoupled.push_back(n + i);
    const std::string name = bordered ? "bordered" : "whole";
    deepdraw::solver::LinearSolverParameters parameters;
    parameters.reuse = deepdraw::solver::LinearSolverParameters::Reuse::always;
    parameters.forcing_term     = 0.1;
    parameters.reuse_iterations = 10;
    deepdraw::solver::LinearSolver solver(parameters);

    fill(A, 0.);
    solver.solve(A, b, x, border, decoupled);
    check_close(name + ": first solve exact",
                relative_residual(A, x, b),
                0.,
                1e-12);
    check_close(name + ": first solve factorised",
                solver.statistics().factorizations,
                1,
                0);

    fill(A, 0.02);
    solver.solve(A, b, x, border, decoupled);
    const auto reused = solver.statistics();
    check_true(name + ": changed matrix solved with the kept factors",
               reused.factorizations == 1 && reused.reused_solves == 1);
    check_true(name + ": by GMRES", reused.gmres_iterations >= 1);
    // The forcing term, and not much less (GMRES stops as it gets there).
    const double achieved = relative_residual(A, x, b);
    check_true(name + ": true residual " + std::to_string(achieved)
                 + " <= forcing term 0.1",
               achieved <= 0.1);

    // Fallback: a forcing term out of reach in 2 iterations.
    deepdraw::solver::LinearSolverParameters strict = parameters;
    strict.forcing_term                             = 1e-12;
    strict.reuse_iterations                         = 2;
    deepdraw::solver::LinearSolver fallback(strict);
    fill(A, 0.);
    fallback.solve(A, b, x, border, decoupled);
    fill(A, 0.2);
    fallback.solve(A, b, x, border, decoupled);
    const auto refactorised = fallback.statistics();
    check_true(name + ": GMRES tried (2 iterations), then factorised",
               refactorised.gmres_iterations == 2
                 && refactorised.factorizations == 2
                 && refactorised.reused_solves == 0);
    check_close(name + ": fallback exact",
                relative_residual(A, x, b),
                0.,
                1e-12);

    // An increment's start: factorise, no GMRES.
    solver.reset_reduction();
    const unsigned int gmres_before = solver.statistics().gmres_iterations;
    fill(A, 0.05);
    solver.solve(A, b, x, border, decoupled);
    check_true(name + ": after reset_reduction() factorised, no GMRES",
               solver.statistics().factorizations == 2
                 && solver.statistics().gmres_iterations == gmres_before);
    check_close(name + ": after reset exact",
                relative_residual(A, x, b),
                0.,
                1e-12);
  }
  check_budget_rule();
  return summary();
}
