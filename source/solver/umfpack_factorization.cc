#include <algorithm>
#include <deepdraw/solver/umfpack_factorization.h>
#include <stdexcept>
#include <string>
#include <utility>

namespace deepdraw
{
  namespace solver
  {
    namespace
    {
      // Measured on square-cup Newton matrices (D35): the symmetric
      // strategy with AMD; a diagonal pivot is accepted only if it is at
      // least 0.1 of its column's largest entry (the default 0.001 took
      // near-zero multiplier diagonals and lost all accuracy).
      std::array<double, UMFPACK_CONTROL>
      make_control()
      {
        std::array<double, UMFPACK_CONTROL> control;
        umfpack_dl_defaults(control.data());
        control[UMFPACK_STRATEGY]            = UMFPACK_STRATEGY_SYMMETRIC;
        control[UMFPACK_ORDERING]            = UMFPACK_ORDERING_AMD;
        control[UMFPACK_SYM_PIVOT_TOLERANCE] = 0.1;
        return control;
      }
    } // namespace


    UmfpackFactorization::UmfpackFactorization()
        : control(make_control())
    {
    }


    UmfpackFactorization::~UmfpackFactorization()
    {
      clear();
    }


    // The CSR matrix is handed over as the CSC storage of its transpose and
    // solved with UMFPACK_At.
    void
    UmfpackFactorization::factorize(const SparseMatrix<double> &matrix)
    {
      const SparsityPattern &pattern = matrix.get_sparsity_pattern();
      if (symbolic == nullptr || !analysed_pattern.matches(pattern))
      {
        clear();
        set_up_storage(pattern);
      }
      std::size_t k = 0;
      for (types::global_dof_index i = 0; i < matrix.m(); ++i)
        for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry, ++k)
          values[position[k]] = entry->value();

      if (numeric != nullptr)
        umfpack_dl_free_numeric(&numeric);
      if (symbolic != nullptr && numeric_factorization(true))
        return;
      // First factorisation of this pattern, or the kept ordering gave a
      // singular or badly conditioned factorisation: analyse afresh.
      if (symbolic != nullptr)
        umfpack_dl_free_symbolic(&symbolic);
      const SuiteSparse_long n      = row_start.size() - 1;
      const int              status = umfpack_dl_symbolic(n,
                                             n,
                                             row_start.data(),
                                             column_index.data(),
                                             values.data(),
                                             &symbolic,
                                             control.data(),
                                             nullptr);
      ++symbolic_analyses;
      if (status != UMFPACK_OK || !numeric_factorization(false))
        throw std::runtime_error("UMFPACK could not factorise the matrix "
                                 "(status "
                                 + std::to_string(status) + ")");
    }


    void
    UmfpackFactorization::solve(const Vector<double> &rhs,
                                Vector<double>       &solution) const
    {
      solution.reinit(rhs.size());
      // Iterative refinement only for a poorly conditioned matrix: it
      // never took a step on the square cup but cost 8 ms per solve.
      std::array<double, UMFPACK_CONTROL> solve_control = control;
      solve_control[UMFPACK_IRSTEP] = reciprocal_condition < 1e-12 ? 2 : 0;
      const int status              = umfpack_dl_solve(UMFPACK_At,
                                          row_start.data(),
                                          column_index.data(),
                                          values.data(),
                                          solution.data(),
                                          rhs.data(),
                                          numeric,
                                          solve_control.data(),
                                          nullptr);
      if (status != UMFPACK_OK)
        throw std::runtime_error("UMFPACK could not solve (status "
                                 + std::to_string(status) + ")");
    }


    void
    UmfpackFactorization::forget_analysis()
    {
      clear();
    }


    unsigned int
    UmfpackFactorization::n_symbolic_analyses() const
    {
      return symbolic_analyses;
    }


    void
    UmfpackFactorization::set_up_storage(const SparsityPattern &pattern)
    {
      analysed_pattern.take(pattern);
      const types::global_dof_index n = pattern.n_rows();
      row_start.assign(n + 1, 0);
      column_index.resize(pattern.n_nonzero_elements());
      values.resize(pattern.n_nonzero_elements());
      position.resize(pattern.n_nonzero_elements());
      // deal.II stores the diagonal first in each row; UMFPACK wants sorted
      // indices.
      std::vector<std::pair<types::global_dof_index, std::size_t>> row;
      std::size_t                                                  k = 0;
      for (types::global_dof_index i = 0; i < n; ++i)
      {
        row.clear();
        for (auto entry = pattern.begin(i); entry != pattern.end(i);
             ++entry, ++k)
          row.emplace_back(entry->column(), k);
        std::sort(row.begin(), row.end());
        row_start[i + 1] = row_start[i] + row.size();
        for (std::size_t j = 0; j < row.size(); ++j)
        {
          column_index[row_start[i] + j] = row[j].first;
          position[row[j].second]        = row_start[i] + j;
        }
      }
    }


    // False if the factorisation is singular or, with a kept ordering
    // (check_condition), its reciprocal condition estimate is below 1e-14:
    // then the ordering is redone. A fresh ordering is accepted as UMFPACK
    // gives it, as deal.II's SparseDirectUMFPACK does.
    bool
    UmfpackFactorization::numeric_factorization(const bool check_condition)
    {
      double    info[UMFPACK_INFO];
      const int status     = umfpack_dl_numeric(row_start.data(),
                                            column_index.data(),
                                            values.data(),
                                            symbolic,
                                            &numeric,
                                            control.data(),
                                            info);
      reciprocal_condition = info[UMFPACK_RCOND];
      const bool good      = status == UMFPACK_OK
                        && (!check_condition || info[UMFPACK_RCOND] > 1e-14);
      if (!good && numeric != nullptr)
        umfpack_dl_free_numeric(&numeric);
      return good;
    }


    void
    UmfpackFactorization::clear()
    {
      if (numeric != nullptr)
        umfpack_dl_free_numeric(&numeric);
      if (symbolic != nullptr)
        umfpack_dl_free_symbolic(&symbolic);
    }
  } // namespace solver
} // namespace deepdraw
