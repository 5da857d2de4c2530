// MUMPS (multifrontal LU, doc/theory.md §5.1, D96) called directly: the
// analysis (ordering and symbolic factorisation) is kept while the sparsity
// pattern stays the same and only the numeric factorisation is redone when
// the values change. Through Amesos every factorisation analysed afresh,
// which made MUMPS slower than UMFPACK (D64). The factors can be single
// precision (SMUMPS): faster, and half the memory, but the solves are then
// only an approximate inverse, which LinearSolver refines (D226).
#ifndef deepdraw_solver_mumps_factorization_h
#define deepdraw_solver_mumps_factorization_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/solver/pattern_snapshot.h>
#include <dmumps_c.h>
#include <memory>
#include <smumps_c.h>
#include <stdexcept>
#include <vector>

namespace deepdraw
{
  namespace solver
  {
    using namespace dealii;

    // MUMPS failed for want of memory or workspace, not because of the
    // matrix (INFOG(1) = -7, -8, -9, -11 to -15, -17, -19, -20): a smaller
    // load increment needs as much, so the run stops instead of cutting
    // back (D177).
    class MumpsMemoryError : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    // The arithmetic of MUMPS' factors (DMUMPS or SMUMPS).
    enum class FactorPrecision
    {
      double_precision,
      single_precision
    };

    class MumpsFactorization
    {
    public:
      // Needs MPI to be initialised (deepdraw's main does): MUMPS runs on
      // MPI_COMM_SELF, or under mpirun on all ranks, every rank calling
      // every function in the same order. `scale`: MUMPS scales rows and
      // columns in each factorisation (ICNTL(8) = 77); false for a well-scaled
      // matrix.
      explicit MumpsFactorization(bool scale = true);
      ~MumpsFactorization();
      MumpsFactorization(const MumpsFactorization &) = delete;
      MumpsFactorization &
      operator=(const MumpsFactorization &)
        = delete;

      // LU factorisation of matrix, with the analysis of the last call if
      // the pattern is the same. Throws std::runtime_error (with MUMPS'
      // INFOG(1), INFOG(2)) if the matrix is singular, MumpsMemoryError if
      // memory or workspace ran out. Under mpirun each rank gives the rows
      // `owned` marks (the matrix split by rows, D214); one rank gives all.
      // Each precision keeps an analysis of its own.
      void
      factorize(const SparseMatrix<double> &matrix,
                const std::vector<bool>    &owned = {},
                FactorPrecision precision = FactorPrecision::double_precision);
      // The precision of the last factorisation, which solve() uses.
      FactorPrecision
      precision() const;
      // Solves with the last factorisation for the columns of `rhs` (one
      // pass through the factors for all of them).
      void
      solve(std::vector<Vector<double>> &rhs_and_solutions);
      void
      solve(const Vector<double> &rhs, Vector<double> &solution);
      // The next factorize() analyses the pattern anew.
      void
      forget_analysis();
      unsigned int
      n_symbolic_analyses() const;
      // Floating-point operations of the last numeric factorisation
      // (RINFOG(3)) and the entries of its factors (INFOG(29)).
      double
      factorization_flops() const;
      double
      factor_entries() const;
      // The fill-reducing ordering of the analysis (INFOG(7): 0 AMD,
      // 4 PORD) and the estimated operations (RINFOG(1)) of each ordering
      // tried; the one with the fewest is kept.
      struct OrderingCandidate
      {
        int    ordering;
        double estimated_flops;
      };
      int
      ordering() const;
      const std::vector<OrderingCandidate> &
      ordering_candidates() const;

    private:
      void
      set_up_pattern(const SparsityPattern   &pattern,
                     const std::vector<bool> &owned);
      // The settings of the constructor, for a new instance.
      template <typename Instance>
      void
      configure(Instance &instance, bool scale);
      // The values of `matrix` in the instance's own arithmetic.
      void
      give_values(const SparseMatrix<double> &matrix);
      // The coordinates of set_up_pattern to an instance.
      template <typename Instance>
      void
      give_pattern(Instance &instance) const;
      // Releases the other precision's instance; creates this one's.
      void
      hold_one_precision(FactorPrecision precision);
      // Analyses the pattern with each ordering; keeps the cheapest.
      template <typename Instance>
      void
      analyse(Instance &instance);
      // Runs MUMPS with `job`; on a workspace shortage (INFOG(1) = -8, -9)
      // it doubles ICNTL(14) and repeats, up to three times.
      template <typename Instance>
      void
      run(Instance &instance, int job);
      template <typename Instance>
      void
      solve_columns(Instance &instance, std::size_t n_columns);

      DMUMPS_STRUC_C data;
      // Created at the first single-precision factorisation; it shares
      // the pattern arrays of `data`.
      std::unique_ptr<SMUMPS_STRUC_C> single_data;
      FactorPrecision    last_precision = FactorPrecision::double_precision;
      bool               scale          = true;
      std::vector<float> single_values;
      std::vector<float> single_right_hand_sides;
      // Under mpirun (D199): MPI_COMM_WORLD, each rank giving the entries
      // of the rows it owns, found at local_positions of the values (D214).
      bool                     distributed = false;
      std::vector<std::size_t> local_positions;
      std::vector<double>      local_values;
      PatternSnapshot          analysed_pattern;
      bool                     has_pattern           = false;
      std::size_t              analysed_pattern_rows = 0;
      bool                     double_factors_held   = false;
      // Whether each precision's instance has analysed the pattern.
      bool                analysed          = false;
      bool                single_analysed   = false;
      unsigned int        symbolic_analyses = 0;
      std::vector<int>    row_index, column_index; // 1-based, as MUMPS wants
      std::vector<double> right_hand_sides;
      std::vector<OrderingCandidate> candidates;
    };
  } // namespace solver
} // namespace deepdraw

#endif
