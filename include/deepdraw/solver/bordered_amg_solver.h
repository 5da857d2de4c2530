// GMRES with algebraic multigrid for the condensed Newton system bordered by
// the positions of force-controlled tools (issue 30, D193):
//   [M C; D E] [x; z] = [f; g],
// M the displacement block. The preconditioner is the block factorisation
// with one AMG V-cycle for M^-1 and the Schur complement S = E - D W, where
// W = M^-1 C is solved to the GMRES tolerance once per hierarchy; one GMRES
// then solves the whole system (doc/theory.md §5).
#ifndef deepdraw_solver_bordered_amg_solver_h
#define deepdraw_solver_bordered_amg_solver_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/solver/amg_solver.h>
#include <deepdraw/solver/bordered_factorization.h>
#include <vector>

namespace deepdraw
{
  namespace solver
  {
    using namespace dealii;

    class BorderedAmgSolver
    {
    public:
      explicit BorderedAmgSolver(const AmgParameters &parameters);

      AmgSolver &
      amg()
      {
        return amg_solver;
      }

      // Builds the hierarchy of `matrix`'s block M and W = M^-1 C; false if
      // GMRES did not solve for W.
      bool
      initialize(const SparseMatrix<double>                 &matrix,
                 const std::vector<types::global_dof_index> &bordered);
      // GMRES on `matrix` (that of initialize() or a later one of the same
      // pattern) to the tolerance; false if it did not get there.
      bool
      solve(const SparseMatrix<double> &matrix,
            const Vector<double>       &rhs,
            Vector<double>             &solution);

      // The preconditioner (block factorisation, one V-cycle for M).
      void
      vmult(Vector<double> &dst, const Vector<double> &src) const;

      // GMRES iterations of the last solve() or initialize().
      unsigned int
      last_iterations() const
      {
        return iterations;
      }

    private:
      AmgParameters parameters;
      // Its split of the matrix into M, C, D and E, and its Schur
      // complement of W = M^-1 C (kept_inverse_columns); no factors.
      BorderedFactorization  split;
      AmgSolver              amg_solver;
      mutable Vector<double> reduced_src, reduced_dst;
      unsigned int           iterations = 0;
    };
  } // namespace solver
} // namespace deepdraw

#endif
