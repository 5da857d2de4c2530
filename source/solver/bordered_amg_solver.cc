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
      this->bordered = bordered;
      split.reduce(matrix, bordered, {});
      amg_solver.initialize(split.reduced_matrix);
      const unsigned int n_b = bordered.size();
      w.resize(n_b);
      iterations = 0;
      for (unsigned int k = 0; k < n_b; ++k)
      {
        if (!amg_solver.solve(split.border_columns[k], w[k]))
          return false;
        iterations += amg_solver.last_iterations();
      }
      // S = E - D W, inverted once.
      schur_inverse = split.corner;
      for (unsigned int k = 0; k < n_b; ++k)
        for (unsigned int l = 0; l < n_b; ++l)
          schur_inverse(k, l) -= split.border_rows[k] * w[l];
      if (n_b > 0)
        schur_inverse.gauss_jordan();
      reduced_src.reinit(split.reduced_matrix.m());
      reduced_dst.reinit(split.reduced_matrix.m());
      return true;
    }


    void
    BorderedAmgSolver::vmult(Vector<double>       &dst,
                             const Vector<double> &src) const
    {
      // y = V-cycle(f), z = S^-1 (g - D y), x = y - W z.
      const auto &role          = split.role;
      const auto &reduced_index = split.reduced_index;
      for (types::global_dof_index i = 0; i < src.size(); ++i)
        if (role[i] == BorderedFactorization::kept)
          reduced_src[reduced_index[i]] = src[i];
      amg_solver.vmult(reduced_dst, reduced_src);
      const unsigned int n_b = bordered.size();
      Vector<double>     border_rhs(n_b), z(n_b);
      for (unsigned int k = 0; k < n_b; ++k)
        border_rhs[k] = src[bordered[k]] - split.border_rows[k] * reduced_dst;
      if (n_b > 0)
        schur_inverse.vmult(z, border_rhs);
      for (unsigned int k = 0; k < n_b; ++k)
        reduced_dst.add(-z[k], w[k]);
      for (types::global_dof_index i = 0; i < src.size(); ++i)
        dst[i] = role[i] == BorderedFactorization::kept
                   ? reduced_dst[reduced_index[i]]
                   : z[split.border_position[i]];
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
