// The direct solve of a bordered Newton system with the factors kept
// (LinearSolver's engine; doc/theory.md §5, D23, D60, D185).
#ifndef deepdraw_solver_bordered_factorization_h
#define deepdraw_solver_bordered_factorization_h

#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_Vector.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/solver/linear_solver.h>
#include <deepdraw/solver/mumps_factorization.h>
#include <deepdraw/solver/umfpack_factorization.h>
#include <memory>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace solver
  {
    using namespace dealii;

    // The direct solve of one Newton system A x = b (the whole one or the
    // condensed one, LinearSolver): the bordered unknowns split off by a
    // Schur complement, the decoupled ones left out (LinearSolver::solve
    // says how), and what is needed to solve again with the same factors
    // kept, so that the factorisation of an earlier matrix can serve as
    // the preconditioner of a later one (D185).
    struct BorderedFactorization
    {
      // Factorises `matrix` and solves matrix * solution = rhs with it.
      void
      factorize_and_solve(
        const std::string                          &type,
        const SparseMatrix<double>                 &matrix,
        const Vector<double>                       &rhs,
        Vector<double>                             &solution,
        const std::vector<types::global_dof_index> &bordered,
        const std::vector<types::global_dof_index> &decoupled);
      // Solves with the factors kept by the last factorize_and_solve():
      // the inverse of that matrix applied to rhs.
      void
      apply_kept_inverse(const Vector<double> &rhs, Vector<double> &solution);
      // Whether apply_kept_inverse() can serve a system of n unknowns.
      bool
      has_kept_inverse(types::global_dof_index n) const;

      // Factorises `matrix` with the chosen package; back_substitute() then
      // solves with it for any number of right-hand sides. `owned`: the
      // rows this rank gives MUMPS (empty: all, on one rank).
      void
      factorize(const std::string          &type,
                const SparseMatrix<double> &matrix,
                const std::vector<bool>    &owned = {});
      void
      back_substitute(const Vector<double> &rhs, Vector<double> &solution);
      // Solves for each column in place (MUMPS: one pass through the
      // factors for all of them).
      void
      back_substitute(std::vector<Vector<double>> &columns);

      std::string type;
      // Under mpirun, the rows of the matrices given to
      // factorize_and_solve() that this rank owns and has complete; the
      // others are not read (D214). Empty: every row.
      std::vector<bool> owned_rows;
      // MUMPS scales rows and columns (the whole system, whose multiplier
      // rows are scaled unlike the displacements); not the condensed one.
      bool scale_matrix = true;
      // The arithmetic of the next MUMPS factorisation (D226).
      FactorPrecision      precision = FactorPrecision::double_precision;
      UmfpackFactorization umfpack;
      // Made on first use: MUMPS needs MPI, which not every caller has.
      std::unique_ptr<MumpsFactorization>   mumps;
      TrilinosWrappers::SparseMatrix        trilinos_matrix;
      std::unique_ptr<Epetra_Vector>        epetra_rhs, epetra_solution;
      std::unique_ptr<Epetra_LinearProblem> epetra_problem;
      std::unique_ptr<Amesos_BaseSolver>    amesos;

      // The reduced matrix M: without the bordered unknowns and the
      // decoupled unknowns left out (role). Its pattern is rebuilt only
      // when the full pattern or the bordered set changes, or an unknown
      // left out is no longer decoupled (see LinearSolver::solve).
      enum Role : unsigned char
      {
        kept,
        bordered,
        left_out
      };
      // Splits `matrix` into M (reduced_matrix), C, D and E (border_columns,
      // border_rows, corner), the reduction rebuilt if needed.
      void
      reduce(const SparseMatrix<double>                 &matrix,
             const std::vector<types::global_dof_index> &bordered,
             const std::vector<types::global_dof_index> &decoupled);
      // Rebuilds role, reduced_index and the reduced pattern if needed.
      void
      update_reduction(const SparsityPattern                      &pattern,
                       const std::vector<types::global_dof_index> &bordered,
                       const std::vector<types::global_dof_index> &decoupled);
      void
      build_reduction(const SparsityPattern                      &pattern,
                      const std::vector<types::global_dof_index> &bordered);
      // Copies the matrix into reduced_matrix and the border blocks; false
      // (and the offending unknowns kept from now on) if an unknown left
      // out has a nonzero off-diagonal entry.
      bool
      copy_reduced(const SparseMatrix<double> &matrix);
      // Rows [begin, end) of copy_reduced; the unknowns found coupled are
      // appended to `coupled`.
      void
      copy_reduced_rows(const SparseMatrix<double>           &matrix,
                        types::global_dof_index               begin,
                        types::global_dof_index               end,
                        std::vector<types::global_dof_index> &coupled);

      const SparsityPattern               *full_pattern  = nullptr;
      std::size_t                          full_nonzeros = 0;
      std::vector<types::global_dof_index> bordered_of_pattern;
      std::vector<Role>                    role;
      std::vector<bool>                    is_decoupled;
      std::vector<types::global_dof_index> reduced_index;
      // owned_rows in M's numbering.
      std::vector<bool>    reduced_owned;
      std::vector<int>     border_position;
      SparsityPattern      reduced_pattern;
      SparseMatrix<double> reduced_matrix;
      // A = [M C; D E] in the bordered unknowns b (columns of C, rows of D).
      std::vector<Vector<double>> border_columns, border_rows;
      FullMatrix<double>          corner;
      LinearSolver::Statistics    statistics;
      bool                        reduction_reset = false;
      // Unknowns the current reduction leaves out.
      types::global_dof_index n_left_out = 0;

      // Kept for apply_kept_inverse(): the size of the factorised system
      // (0: nothing kept), the bordered unknowns, M^-1 C, the inverse Schur
      // complement and the diagonal of the unknowns left out.
      types::global_dof_index              kept_size = 0;
      std::vector<types::global_dof_index> kept_bordered;
      std::vector<Vector<double>>          kept_inverse_columns;
      FullMatrix<double>                   kept_schur_inverse;
      Vector<double>                       kept_left_out_diagonal;

      // From kept_inverse_columns (M^-1 C of kept_bordered): the inverse
      // Schur complement and the diagonal of the unknowns left out, kept
      // for expand_solution() on systems of matrix's size.
      void
      keep_schur_complement(const SparseMatrix<double> &matrix);
      // The kept unknowns of a whole-system vector, in M's numbering.
      void
      restrict_to_reduced(const Vector<double> &full,
                          Vector<double>       &reduced) const;
      // From M^-1 f (y, overwritten) to the solution of the whole system:
      // the bordered unknowns by the kept Schur complement, those left out
      // by their diagonal.
      void
      expand_solution(Vector<double>       &y,
                      const Vector<double> &rhs,
                      Vector<double>       &solution) const;
    };

  } // namespace solver
} // namespace deepdraw

#endif
