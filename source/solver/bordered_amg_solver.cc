#include <deepdraw/solver/bordered_amg_solver.h>

namespace deepdraw
{
  namespace solver
  {
    BorderedAmgSolver::BorderedAmgSolver(const AmgParameters &parameters)
        : parameters(parameters)
        , amg_solver(parameters)
    {
    }


    bool
    BorderedAmgSolver::initialize(
      const SparseMatrix<double>                 &matrix,
      const std::vector<types::global_dof_index> &bordered)
    {
      split.kept_size     = 0;
      split.kept_bordered = bordered;
      split.reduce(matrix, bordered, {});
      amg_solver.initialize(split.reduced_matrix);
      auto &w = split.kept_inverse_columns;
      w.resize(bordered.size());
      iterations = 0;
      for (unsigned int k = 0; k < bordered.size(); ++k)
      {
        if (!amg_solver.solve(split.border_columns[k], w[k]))
          return false;
        iterations += amg_solver.last_iterations();
      }
      split.keep_schur_complement(matrix);
      reduced_src.reinit(split.reduced_matrix.m());
      reduced_dst.reinit(split.reduced_matrix.m());
      return true;
    }


    void
    BorderedAmgSolver::vmult(Vector<double>       &dst,
                             const Vector<double> &src) const
    {
      // y = V-cycle(f), then z = S^-1 (g - D y), x = y - W z.
      split.restrict_to_reduced(src, reduced_src);
      amg_solver.vmult(reduced_dst, reduced_src);
      split.expand_solution(reduced_dst, src, dst);
    }


    bool
    BorderedAmgSolver::solve(const SparseMatrix<double> &matrix,
                             const Vector<double>       &rhs,
                             Vector<double>             &solution)
    {
      return solve_by_gmres(matrix,
                            *this,
                            parameters,
                            rhs,
                            solution,
                            iterations);
    }
  } // namespace solver
} // namespace deepdraw
