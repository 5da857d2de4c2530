#include <Amesos_Klu.h>
#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <deal.II/base/parallel.h>
#include <deepdraw/parallel/ranks.h>
#include <deepdraw/solver/bordered_factorization.h>
#include <iterator>
#include <mutex>
#include <stdexcept>

namespace deepdraw
{
  namespace solver
  {
    void
    BorderedFactorization::factorize(const std::string          &type,
                                     const SparseMatrix<double> &matrix,
                                     const std::vector<bool>    &owned)
    {
      this->type = type;
      if (type == "UMFPACK")
      {
        umfpack.factorize(matrix);
        return;
      }
      if (type == "MUMPS")
      {
        if (mumps == nullptr)
          mumps = std::make_unique<MumpsFactorization>(scale_matrix);
        mumps->factorize(matrix, owned, precision);
        return;
      }
      // KLU through Amesos. The old solver refers to the old problem and
      // matrix: release it first.
      amesos.reset();
      // A fresh copy: reinit() of a filled matrix keeps its old pattern,
      // and entries that were zero then (open contact pairs) were lost.
      trilinos_matrix.clear();
      trilinos_matrix.reinit(matrix);
      const Epetra_CrsMatrix &epetra = trilinos_matrix.trilinos_matrix();
      epetra_rhs      = std::make_unique<Epetra_Vector>(epetra.RangeMap());
      epetra_solution = std::make_unique<Epetra_Vector>(epetra.DomainMap());
      epetra_problem
        = std::make_unique<Epetra_LinearProblem>(const_cast<Epetra_CrsMatrix *>(
                                                   &epetra),
                                                 epetra_solution.get(),
                                                 epetra_rhs.get());
      amesos = std::make_unique<Amesos_Klu>(*epetra_problem);
      if (amesos->SymbolicFactorization() != 0
          || amesos->NumericFactorization() != 0)
        throw std::runtime_error("Amesos " + type
                                 + " could not factorise the matrix");
    }


    void
    BorderedFactorization::back_substitute(const Vector<double> &rhs,
                                           Vector<double>       &solution)
    {
      solution.reinit(rhs.size());
      if (type == "UMFPACK")
      {
        umfpack.solve(rhs, solution);
        return;
      }
      if (type == "MUMPS")
      {
        mumps->solve(rhs, solution);
        return;
      }
      for (unsigned int i = 0; i < rhs.size(); ++i)
        (*epetra_rhs)[i] = rhs[i];
      if (amesos->Solve() != 0)
        throw std::runtime_error("Amesos " + type + " could not solve");
      for (unsigned int i = 0; i < solution.size(); ++i)
        solution[i] = (*epetra_solution)[i];
    }


    void
    BorderedFactorization::back_substitute(std::vector<Vector<double>> &columns)
    {
      if (type == "MUMPS")
      {
        mumps->solve(columns);
        return;
      }
      Vector<double> solution;
      for (Vector<double> &column : columns)
      {
        back_substitute(column, solution);
        column.swap(solution);
      }
    }


    namespace
    {
      // The reduced pattern is also rebuilt, to shrink the factorised
      // matrix, when more than this fraction of the unknowns it keeps has
      // become decoupled (contact pairs that opened).
      constexpr double shrink_fraction = 0.25;
    } // namespace


    void
    BorderedFactorization::update_reduction(
      const SparsityPattern                      &pattern,
      const std::vector<types::global_dof_index> &bordered,
      const std::vector<types::global_dof_index> &decoupled)
    {
      const types::global_dof_index n = pattern.n_rows();
      is_decoupled.assign(n, false);
      for (const auto i : decoupled)
        is_decoupled[i] = true;
      bool rebuild
        = full_pattern != &pattern
          || full_nonzeros != pattern.n_nonzero_elements()
          || bordered_of_pattern != bordered || role.size() != n
          || (reduction_reset && (n_left_out > 0 || !decoupled.empty()));
      // A reset cannot change a reduction that leaves nothing out before or
      // after (that of the condensed system): it is kept (D98).
      reduction_reset                = false;
      types::global_dof_index n_kept = 0, n_kept_decoupled = 0;
      for (types::global_dof_index i = 0; i < n && !rebuild; ++i)
        if (role[i] == left_out && !is_decoupled[i])
          rebuild = true;
        else if (role[i] == kept)
        {
          ++n_kept;
          n_kept_decoupled += is_decoupled[i];
        }
      if (rebuild || n_kept_decoupled > shrink_fraction * n_kept)
      {
        full_pattern        = &pattern;
        full_nonzeros       = pattern.n_nonzero_elements();
        bordered_of_pattern = bordered;
        build_reduction(pattern, bordered);
      }
    }


    void
    BorderedFactorization::build_reduction(
      const SparsityPattern                      &pattern,
      const std::vector<types::global_dof_index> &bordered)
    {
      const types::global_dof_index n = pattern.n_rows();
      role.assign(n, kept);
      n_left_out = 0;
      for (types::global_dof_index i = 0; i < n; ++i)
        if (is_decoupled[i])
        {
          role[i] = left_out;
          ++n_left_out;
        }
      border_position.assign(n, -1);
      for (unsigned int k = 0; k < bordered.size(); ++k)
      {
        role[bordered[k]]            = Role::bordered;
        border_position[bordered[k]] = k;
      }
      reduced_index.assign(n, numbers::invalid_dof_index);
      reduced_owned.clear();
      types::global_dof_index n_m = 0;
      for (types::global_dof_index i = 0; i < n; ++i)
        if (role[i] == kept)
        {
          reduced_index[i] = n_m++;
          if (!owned_rows.empty())
            reduced_owned.push_back(owned_rows[i]);
        }

      std::vector<unsigned int> row_lengths(n_m, 0);
      for (types::global_dof_index i = 0; i < n; ++i)
        if (role[i] == kept)
          for (auto entry = pattern.begin(i); entry != pattern.end(i); ++entry)
            row_lengths[reduced_index[i]] += role[entry->column()] == kept;
      reduced_pattern.reinit(n_m, n_m, row_lengths);
      std::vector<types::global_dof_index> columns;
      for (types::global_dof_index i = 0; i < n; ++i)
        if (role[i] == kept)
        {
          columns.clear();
          for (auto entry = pattern.begin(i); entry != pattern.end(i); ++entry)
            if (role[entry->column()] == kept)
              columns.push_back(reduced_index[entry->column()]);
          std::sort(columns.begin(), columns.end());
          reduced_pattern.add_entries(reduced_index[i],
                                      columns.begin(),
                                      columns.end(),
                                      true);
        }
      reduced_pattern.compress();
      reduced_matrix.reinit(reduced_pattern);
      ++statistics.reductions;
    }


    void
    BorderedFactorization::reduce(
      const SparseMatrix<double>                 &matrix,
      const std::vector<types::global_dof_index> &bordered,
      const std::vector<types::global_dof_index> &decoupled)
    {
      update_reduction(matrix.get_sparsity_pattern(), bordered, decoupled);
      while (!copy_reduced(matrix))
      {
      }
    }


    bool
    BorderedFactorization::copy_reduced(const SparseMatrix<double> &matrix)
    {
      const types::global_dof_index n   = matrix.m();
      const types::global_dof_index n_m = reduced_pattern.n_rows();
      const unsigned int            n_b = bordered_of_pattern.size();
      border_columns.assign(n_b, Vector<double>(n_m));
      border_rows.assign(n_b, Vector<double>(n_m));
      corner.reinit(n_b, n_b);
      std::vector<types::global_dof_index> coupled;
      std::mutex                           coupled_mutex;
      // The rows are independent: both cores (D98).
      dealii::parallel::apply_to_subranges(
        types::global_dof_index(0),
        n,
        [&](const types::global_dof_index begin,
            const types::global_dof_index end)
        {
          std::vector<types::global_dof_index> found;
          copy_reduced_rows(matrix, begin, end, found);
          if (!found.empty())
          {
            std::lock_guard<std::mutex> lock(coupled_mutex);
            coupled.insert(coupled.end(), found.begin(), found.end());
          }
        },
        2048);
      if (coupled.empty())
      {
        // Each rank copied the rows it owns (D214).
        if (!owned_rows.empty())
        {
          for (auto *border : {&border_columns, &border_rows})
            for (Vector<double> &vector : *border)
              parallel::sum(vector.begin(), vector.size());
          if (n_b > 0)
            parallel::sum(&corner(0, 0), n_b * n_b);
        }
        return true;
      }
      // Not decoupled after all: keep these from now on.
      for (const auto j : coupled)
        is_decoupled[j] = false;
      build_reduction(*full_pattern, bordered_of_pattern);
      return false;
    }


    void
    BorderedFactorization::copy_reduced_rows(
      const SparseMatrix<double>           &matrix,
      const types::global_dof_index         begin,
      const types::global_dof_index         end,
      std::vector<types::global_dof_index> &coupled)
    {
      // The reduced rows keep the order of the full rows (diagonal first,
      // then ascending columns, and the renumbering is monotone): copy in
      // step instead of searching each entry.
      for (types::global_dof_index i = begin; i < end; ++i)
      {
        if (!owned_rows.empty() && !owned_rows[i])
          continue;
        const Role role_i = role[i];
        if (role_i == left_out)
        {
          for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
            if (entry->column() != i && entry->value() != 0.)
            {
              coupled.push_back(i);
              break;
            }
          continue;
        }
        const int bi            = border_position[i];
        auto      reduced_entry = role_i == kept
                                    ? reduced_matrix.begin(reduced_index[i])
                                    : reduced_matrix.end();
        for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
        {
          const auto   j      = entry->column();
          const double value  = entry->value();
          const Role   role_j = role[j];
          if (role_j == left_out)
          {
            if (value != 0.)
              coupled.push_back(j);
          }
          else if (role_i == kept && role_j == kept)
          {
            AssertThrow(reduced_entry->column() == reduced_index[j],
                        ExcInternalError());
            reduced_entry->value() = value;
            ++reduced_entry;
          }
          else if (role_i == kept)
            border_columns[border_position[j]][reduced_index[i]] = value;
          else if (role_j == kept)
            border_rows[bi][reduced_index[j]] = value;
          else
            corner(bi, border_position[j]) = value;
        }
      }
    }


    void
    BorderedFactorization::factorize_and_solve(
      const std::string                          &type,
      const SparseMatrix<double>                 &matrix,
      const Vector<double>                       &rhs,
      Vector<double>                             &solution,
      const std::vector<types::global_dof_index> &bordered,
      const std::vector<types::global_dof_index> &decoupled)
    {
      const types::global_dof_index n = matrix.m();
      ++statistics.factorizations;
      statistics.unknowns = n;
      kept_size           = 0;
      kept_bordered       = bordered;
      if (bordered.empty() && decoupled.empty())
      {
        role.clear();
        statistics.factorized_unknowns = n;
        factorize(type, matrix, owned_rows);
        ++statistics.numeric_factorizations;
        back_substitute(rhs, solution);
        kept_size = n;
        return;
      }

      reduce(matrix, bordered, decoupled);
      const types::global_dof_index n_m = reduced_pattern.n_rows();
      statistics.factorized_unknowns    = n_m;
      factorize(type, reduced_matrix, reduced_owned);
      ++statistics.numeric_factorizations;
      // columns: f, then C (the border columns); M^-1 of all at once.
      std::vector<Vector<double>> columns(1, Vector<double>(n_m));
      restrict_to_reduced(rhs, columns[0]);
      columns.insert(columns.end(),
                     border_columns.begin(),
                     border_columns.end());
      back_substitute(columns);
      Vector<double> y;
      y.swap(columns[0]);
      kept_inverse_columns.assign(std::make_move_iterator(columns.begin() + 1),
                                  std::make_move_iterator(columns.end()));
      keep_schur_complement(matrix);
      expand_solution(y, rhs, solution);
    }


    void
    BorderedFactorization::keep_schur_complement(
      const SparseMatrix<double> &matrix)
    {
      // S = E - D M^-1 C, kept inverted with M^-1 C.
      const types::global_dof_index n   = matrix.m();
      const unsigned int            n_b = kept_inverse_columns.size();
      kept_schur_inverse                = corner;
      for (unsigned int k = 0; k < n_b; ++k)
        for (unsigned int l = 0; l < n_b; ++l)
          kept_schur_inverse(k, l) -= border_rows[k] * kept_inverse_columns[l];
      if (n_b > 0)
        kept_schur_inverse.gauss_jordan();
      kept_left_out_diagonal.reinit(n);
      for (types::global_dof_index i = 0; i < n; ++i)
        if (role[i] == left_out)
          kept_left_out_diagonal[i] = matrix.diag_element(i);
      kept_size = n;
    }


    void
    BorderedFactorization::restrict_to_reduced(const Vector<double> &full,
                                               Vector<double> &reduced) const
    {
      for (types::global_dof_index i = 0; i < full.size(); ++i)
        if (role[i] == kept)
          reduced[reduced_index[i]] = full[i];
    }


    void
    BorderedFactorization::apply_kept_inverse(const Vector<double> &rhs,
                                              Vector<double>       &solution)
    {
      AssertThrow(has_kept_inverse(rhs.size()), ExcInternalError());
      if (role.empty())
      {
        back_substitute(rhs, solution);
        return;
      }
      Vector<double> reduced_rhs(reduced_pattern.n_rows()), y;
      restrict_to_reduced(rhs, reduced_rhs);
      back_substitute(reduced_rhs, y);
      expand_solution(y, rhs, solution);
    }


    bool
    BorderedFactorization::has_kept_inverse(
      const types::global_dof_index n) const
    {
      return kept_size > 0 && kept_size == n;
    }


    void
    BorderedFactorization::expand_solution(Vector<double>       &y,
                                           const Vector<double> &rhs,
                                           Vector<double>       &solution) const
    {
      // z = S^-1 (f_b - D M^-1 f), x = M^-1 f - M^-1 C z.
      const unsigned int n_b = kept_bordered.size();
      Vector<double>     z(n_b);
      if (n_b > 0)
      {
        Vector<double> border_rhs(n_b);
        for (unsigned int k = 0; k < n_b; ++k)
          border_rhs[k] = rhs[kept_bordered[k]] - border_rows[k] * y;
        kept_schur_inverse.vmult(z, border_rhs);
        for (unsigned int k = 0; k < n_b; ++k)
          y.add(-z[k], kept_inverse_columns[k]);
      }
      // A decoupled unknown's row is its diagonal alone.
      solution.reinit(kept_size);
      for (types::global_dof_index i = 0; i < kept_size; ++i)
        switch (role[i])
        {
          case kept:
            solution[i] = y[reduced_index[i]];
            break;
          case bordered:
            solution[i] = z[border_position[i]];
            break;
          case left_out:
            solution[i] = rhs[i] / kept_left_out_diagonal[i];
            break;
        }
    }
  } // namespace solver
} // namespace deepdraw
