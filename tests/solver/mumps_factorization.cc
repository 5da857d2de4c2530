// MumpsFactorization (D96), MUMPS called directly with its analysis kept,
// on the shape of a contact Newton matrix: a chain of displacement-like
// unknowns, a multiplier per node with a zero diagonal when closed (MUMPS
// must pivot off the diagonal), and a bordered unknown. Checked against a
// dense Gauss–Jordan inverse of the same matrix:
// - the solution to 1e-14 (relative; achieved 2-4e-16 on this
//   well-conditioned 61 x 61 system, 1e-14 leaves room for other pivot
//   orders);
// - the analysis is kept while the pattern stays (one analysis for four
//   value sets), redone for a new pattern and after forget_analysis();
// - two right-hand sides solved at once equal the single solves to 1e-14;
// - of the orderings AMD and PORD, the one with fewer estimated
//   operations is used (D98; PORD only from 1000 unknowns, D186), and a
//   factorisation without scaling gives the same solution;
// - a singular matrix is reported with MUMPS' status, not solved;
// - LinearSolver with `Type = MUMPS` and the holder bordered equals the
//   dense solution to 1e-14, with one analysis for three increments
//   (reset_reduction() between them keeps MUMPS' analysis, D97);
// - single-precision factors (D226) solve to float accuracy only: between
//   1e-10 and 1e-5 off the dense solution (float's 6e-8 times the
//   condition of this small system; double is 2-4e-16), while the same
//   object's double factorisation is exact again; only one precision's
//   instance is held (the other released with its factors, so a switch
//   analyses anew), and its analysis is kept while the precision stays;
// - LinearSolver with `Factorisation precision = single` refines the
//   single-precision solve by GMRES to its tolerance (1e-10 here, so that
//   GMRES must iterate), counts the factorisation, and factorises a
//   stage's first increment (reset_reduction(false)) in double, exactly.
#include "contact_like_pattern.h"
#include "test_utilities.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/solver/linear_solver.h>
#include <deepdraw/solver/mumps_factorization.h>
#include <stdexcept>
#include <string>
#include <vector>

using namespace dealii;
using namespace deepdraw_test;

namespace
{
  constexpr unsigned int n = 30;

  // Unsymmetric; a closed pair has a zero multiplier diagonal.
  void
  fill(SparseMatrix<double> &A, const unsigned int state)
  {
    A = 0.;
    for (unsigned int i = 0; i < n; ++i)
    {
      const bool closed = (i + state) % 3 == 0;
      A.set(i, i, 2. + 0.1 * i);
      if (i > 0)
        A.set(i, i - 1, -1.);
      if (i + 1 < n)
        A.set(i, i + 1, -0.9);
      A.set(i, n + i, closed ? -1. - 0.01 * i : 0.);
      A.set(n + i, i, closed ? 1. : 0.);
      A.set(n + i, n + i, closed ? 0. : 0.5);
      A.set(n + i, 2 * n, closed ? 0.5 : 0.);
      A.set(2 * n, n + i, closed ? 1. : 0.);
    }
    A.set(2 * n, 2 * n, 1.);
  }

  Vector<double>
  dense_solution(const SparseMatrix<double> &A, const Vector<double> &b)
  {
    FullMatrix<double> inverse(A.m(), A.n());
    inverse.copy_from(A);
    inverse.gauss_jordan();
    Vector<double> x(b.size());
    inverse.vmult(x, b);
    return x;
  }

  double
  relative_difference(Vector<double> x, const Vector<double> &reference)
  {
    x -= reference;
    return x.l2_norm() / reference.l2_norm();
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  SparsityPattern                  pattern;
  make_contact_like_pattern(n, pattern);
  SparseMatrix<double> A(pattern);
  Vector<double>       b(2 * n + 1), c(2 * n + 1);
  for (unsigned int i = 0; i < b.size(); ++i)
  {
    b[i] = 1. + std::sin(1. + i);
    c[i] = std::cos(0.3 * i);
  }

  deepdraw::solver::MumpsFactorization mumps;
  for (unsigned int state = 0; state < 4; ++state)
  {
    fill(A, state);
    mumps.factorize(A);
    Vector<double> x;
    mumps.solve(b, x);
    check_close("state " + std::to_string(state)
                  + ": solution against the dense inverse",
                relative_difference(x, dense_solution(A, b)),
                0.,
                1e-14);
  }
  check_close("one analysis for four value sets",
              mumps.n_symbolic_analyses(),
              1,
              0);
  check_true("flops of the factorisation reported",
             mumps.factorization_flops() > 0.);
  // D186: below 1000 unknowns only AMD is tried (PORD ends the process on
  // tiny graphs); the grid below tries both (D98).
  check_close("61 unknowns: AMD alone tried",
              mumps.ordering_candidates().size(),
              1,
              0);
  check_close("61 unknowns: AMD used", mumps.ordering(), 0, 0);

  // A 9-point grid operator (a sheet's pattern in miniature), on which the
  // two orderings differ: the factorisation's operations (RINFOG(3)) are
  // the estimate of the ordering chosen, i.e. its analysis is the one
  // kept. Diagonally dominant, so no pivot is delayed and the two agree
  // to rounding (1e-9 relative).
  {
    const unsigned int     side = 40, n_grid = side * side;
    DynamicSparsityPattern grid_dsp(n_grid, n_grid);
    for (unsigned int i = 0; i < n_grid; ++i)
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
        {
          const int x = i % side + dx, y = i / side + dy;
          if (x >= 0 && y >= 0 && x < int(side) && y < int(side))
            grid_dsp.add(i, y * side + x);
        }
    SparsityPattern grid_pattern;
    grid_pattern.copy_from(grid_dsp);
    SparseMatrix<double> grid(grid_pattern);
    for (unsigned int i = 0; i < n_grid; ++i)
      for (auto entry = grid.begin(i); entry != grid.end(i); ++entry)
        entry->value() = entry->column() == i ? 9. : -1. + 0.01 * (i % 7);
    deepdraw::solver::MumpsFactorization grid_mumps(false);
    grid_mumps.factorize(grid);
    const auto &tried = grid_mumps.ordering_candidates();
    const auto &fewest
      = *std::min_element(tried.begin(),
                          tried.end(),
                          [](const auto &a, const auto &b)
                          { return a.estimated_flops < b.estimated_flops; });
    std::cout << "  grid " << side << " x " << side << ": AMD "
              << tried[0].estimated_flops << ", PORD "
              << tried[1].estimated_flops << " flops, used "
              << grid_mumps.ordering() << std::endl;
    check_true("grid: the orderings differ",
               tried[0].estimated_flops != tried[1].estimated_flops);
    check_close("grid: the cheaper ordering used",
                grid_mumps.ordering(),
                fewest.ordering,
                0);
    check_close("grid: its analysis kept (operations as estimated)",
                grid_mumps.factorization_flops() / fewest.estimated_flops,
                1.,
                1e-9);
  }

  // Without scaling (the condensed system, D98): the same solution.
  deepdraw::solver::MumpsFactorization unscaled(false);
  unscaled.factorize(A);
  Vector<double> x_unscaled;
  unscaled.solve(b, x_unscaled);
  check_close("unscaled: solution against the dense inverse",
              relative_difference(x_unscaled, dense_solution(A, b)),
              0.,
              1e-14);

  std::vector<Vector<double>> columns{b, c};
  mumps.solve(columns);
  Vector<double> x_b, x_c;
  mumps.solve(b, x_b);
  mumps.solve(c, x_c);
  check_close("two right-hand sides at once: first",
              relative_difference(columns[0], x_b),
              0.,
              1e-14);
  check_close("two right-hand sides at once: second",
              relative_difference(columns[1], x_c),
              0.,
              1e-14);

  mumps.forget_analysis();
  mumps.factorize(A);
  check_close("analysed again after forget_analysis()",
              mumps.n_symbolic_analyses(),
              2,
              0);

  // A new pattern (the chain alone) is analysed anew.
  DynamicSparsityPattern chain_dsp(n, n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = (i > 0 ? i - 1 : 0); j <= std::min(i + 1, n - 1); ++j)
      chain_dsp.add(i, j);
  SparsityPattern chain_pattern;
  chain_pattern.copy_from(chain_dsp);
  SparseMatrix<double> chain(chain_pattern);
  for (unsigned int i = 0; i < n; ++i)
  {
    chain.set(i, i, 2.);
    if (i > 0)
      chain.set(i, i - 1, -1.);
    if (i + 1 < n)
      chain.set(i, i + 1, -1.);
  }
  mumps.factorize(chain);
  check_close("analysed again for a new pattern",
              mumps.n_symbolic_analyses(),
              3,
              0);

  // Singular: the last row of the chain is zero.
  chain.set(n - 1, n - 1, 0.);
  chain.set(n - 1, n - 2, 0.);
  chain.set(n - 2, n - 1, 0.);
  bool        reported = false;
  std::string message;
  try
  {
    mumps.factorize(chain);
  }
  catch (const std::runtime_error &error)
  {
    reported = true;
    message  = error.what();
  }
  std::cout << "  singular matrix: " << message << std::endl;
  check_true("a singular matrix is reported",
             reported && message.find("INFOG(1)") != std::string::npos);

  // Through LinearSolver, with the last unknown bordered (D23).
  deepdraw::solver::LinearSolverParameters parameters;
  parameters.type = "MUMPS";
  deepdraw::solver::LinearSolver solver(parameters);
  for (unsigned int state = 0; state < 3; ++state)
  {
    // As at the start of an increment (D97: the analysis stays).
    solver.reset_reduction();
    fill(A, state);
    Vector<double> x;
    solver.solve(A, b, x, {2 * n});
    check_close("LinearSolver (MUMPS, bordered), state "
                  + std::to_string(state),
                relative_difference(x, dense_solution(A, b)),
                0.,
                1e-14);
  }
  check_close("LinearSolver keeps the analysis, across reset_reduction()",
              solver.statistics().symbolic_analyses,
              1,
              0);

  // Single-precision factors (D226).
  {
    using deepdraw::solver::FactorPrecision;
    fill(A, 1);
    const Vector<double>                 exact = dense_solution(A, b);
    deepdraw::solver::MumpsFactorization two_precisions;
    Vector<double>                       x;
    two_precisions.factorize(A, {}, FactorPrecision::single_precision);
    two_precisions.solve(b, x);
    const double single_error = relative_difference(x, exact);
    std::cout << "  single precision: " << single_error << std::endl;
    check_true("single precision: float accuracy, not double's",
               single_error > 1e-10 && single_error < 1e-5
                 && two_precisions.precision()
                      == FactorPrecision::single_precision);
    two_precisions.factorize(A);
    two_precisions.solve(b, x);
    check_close("double after single: exact again",
                relative_difference(x, exact),
                0.,
                1e-14);
    two_precisions.factorize(A, {}, FactorPrecision::single_precision);
    two_precisions.factorize(A, {}, FactorPrecision::single_precision);
    check_close("an analysis per switch of precision, kept while it stays",
                two_precisions.n_symbolic_analyses(),
                3,
                0);

    parameters.precision
      = deepdraw::solver::LinearSolverParameters::Precision::single;
    parameters.single_precision_tolerance = 1e-10;
    deepdraw::solver::LinearSolver refined(parameters);
    refined.reset_reduction(true);
    refined.solve(A, b, x, {2 * n});
    const auto counts = refined.statistics();
    std::cout << "  refined: " << relative_difference(x, exact) << " after "
              << counts.gmres_iterations << " GMRES iterations" << std::endl;
    check_true("single precision refined: counted, GMRES iterated",
               counts.single_precision_factorizations == 1
                 && counts.single_precision_fallbacks == 0
                 && counts.gmres_iterations > 0);
    // |x - x*| <= cond |b - A x| / |b|: 1e-10 with room for the condition.
    check_close("single precision refined to its tolerance",
                relative_difference(x, exact),
                0.,
                1e-8);
    refined.reset_reduction(false);
    refined.solve(A, b, x, {2 * n});
    check_close("a stage's first increment: double, exact",
                relative_difference(x, exact),
                0.,
                1e-14);
    check_close("a stage's first increment: no single factorisation",
                refined.statistics().single_precision_factorizations,
                1,
                0);
  }
  return summary();
}
