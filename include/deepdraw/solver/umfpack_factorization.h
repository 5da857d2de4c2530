// UMFPACK called directly (doc/theory.md §5.1, D27, D35): the symbolic
// analysis (fill-reducing ordering) is kept while the sparsity pattern stays
// the same, and only the numeric factorisation is redone when the values
// change. deal.II's SparseDirectUMFPACK redoes the analysis every time.
#ifndef deepdraw_solver_umfpack_factorization_h
#define deepdraw_solver_umfpack_factorization_h

#include <array>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/solver/pattern_snapshot.h>
#include <umfpack.h>
#include <vector>

namespace deepdraw
{
  namespace solver
  {
    using namespace dealii;

    class UmfpackFactorization
    {
    public:
      UmfpackFactorization();
      ~UmfpackFactorization();
      UmfpackFactorization(const UmfpackFactorization &) = delete;
      UmfpackFactorization &
      operator=(const UmfpackFactorization &)
        = delete;

      // LU factorisation of matrix; the ordering of the last call is
      // reused if the pattern is the same and the factorisation with it is
      // good. Throws std::runtime_error if the matrix is singular.
      void
      factorize(const SparseMatrix<double> &matrix);
      // Solves with the last factorisation.
      void
      solve(const Vector<double> &rhs, Vector<double> &solution) const;
      // The next factorize() analyses the pattern anew.
      void
      forget_analysis();
      // Symbolic analyses (orderings) done so far.
      unsigned int
      n_symbolic_analyses() const;

    private:
      void
      set_up_storage(const SparsityPattern &pattern);
      bool
      numeric_factorization(bool check_condition);
      void
      clear();

      const std::array<double, UMFPACK_CONTROL> control;
      double                                    reciprocal_condition = 1.;
      void                                     *symbolic             = nullptr;
      void                                     *numeric              = nullptr;
      unsigned int                              symbolic_analyses    = 0;
      std::vector<SuiteSparse_long>             row_start, column_index;
      std::vector<double>                       values;
      PatternSnapshot                           analysed_pattern;
      // Storage position of the k-th entry of the deal.II matrix.
      std::vector<std::size_t> position;
    };
  } // namespace solver
} // namespace deepdraw

#endif
