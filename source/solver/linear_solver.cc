#include <Amesos_Klu.h>
#include <Amesos_Mumps.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_Vector.h>
#include <algorithm>
#include <array>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deepdraw/solver/linear_solver.h>
#include <stdexcept>
#include <umfpack.h>

namespace deepdraw
{
  namespace solver
  {
    void
    LinearSolverParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.declare_entry("Type",
                        "UMFPACK",
                        Patterns::Selection("UMFPACK|MUMPS|KLU"),
                        "Direct solver of the Newton system: UMFPACK "
                        "(SuiteSparse, called directly), MUMPS or KLU "
                        "(through Trilinos Amesos).");
      prm.leave_subsection();
    }


    void
    LinearSolverParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      type = prm.get("Type");
      prm.leave_subsection();
    }


    namespace
    {
      // UMFPACK called directly so that the symbolic analysis (fill-reducing
      // ordering) is kept while the pattern stays the same: Newton changes
      // the values only, and contact state changes only zero entries of a
      // fixed pattern. deal.II's SparseDirectUMFPACK redoes it every time.
      // The CSR matrix is handed over as the CSC storage of its transpose
      // and solved with UMFPACK_At.
      class UmfpackFactorization
      {
      public:
        ~UmfpackFactorization()
        {
          clear();
        }

        void
        factorize(const SparseMatrix<double> &matrix)
        {
          const SparsityPattern &pattern = matrix.get_sparsity_pattern();
          if (!has_pattern(pattern))
          {
            clear();
            set_up_storage(pattern);
          }
          std::size_t k = 0;
          for (types::global_dof_index i = 0; i < matrix.m(); ++i)
            for (auto entry = matrix.begin(i); entry != matrix.end(i);
                 ++entry, ++k)
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
          if (status != UMFPACK_OK || !numeric_factorization(false))
            throw std::runtime_error("UMFPACK could not factorise the matrix "
                                     "(status "
                                     + std::to_string(status) + ")");
        }

        void
        solve(const Vector<double> &rhs, Vector<double> &solution) const
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

      private:
        // A pattern object may be rebuilt in place: compare the entries
        // (cheap next to a factorisation).
        bool
        has_pattern(const SparsityPattern &pattern) const
        {
          if (symbolic == nullptr || pattern.n_rows() + 1 != row_start.size()
              || pattern.n_nonzero_elements() != column_index.size())
            return false;
          std::size_t k = 0;
          for (types::global_dof_index i = 0; i < pattern.n_rows(); ++i)
            for (auto entry = pattern.begin(i); entry != pattern.end(i);
                 ++entry, ++k)
              if (static_cast<types::global_dof_index>(
                    column_index[position[k]])
                  != entry->column())
                return false;
          return true;
        }

        void
        set_up_storage(const SparsityPattern &pattern)
        {
          const types::global_dof_index n = pattern.n_rows();
          row_start.assign(n + 1, 0);
          column_index.resize(pattern.n_nonzero_elements());
          values.resize(pattern.n_nonzero_elements());
          position.resize(pattern.n_nonzero_elements());
          // deal.II stores the diagonal first in each row; UMFPACK wants
          // sorted indices.
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
        // (check_condition), its reciprocal condition estimate is below
        // 1e-14: then the ordering is redone. A fresh ordering is accepted
        // as UMFPACK gives it, as deal.II's SparseDirectUMFPACK does.
        bool
        numeric_factorization(const bool check_condition)
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
          const bool good
            = status == UMFPACK_OK
              && (!check_condition || info[UMFPACK_RCOND] > 1e-14);
          if (!good && numeric != nullptr)
            umfpack_dl_free_numeric(&numeric);
          return good;
        }

        void
        clear()
        {
          if (numeric != nullptr)
            umfpack_dl_free_numeric(&numeric);
          if (symbolic != nullptr)
            umfpack_dl_free_symbolic(&symbolic);
        }

        // Measured on square-cup Newton matrices (D35): the symmetric
        // strategy with AMD; a diagonal pivot is accepted only if it is at
        // least 0.1 of its column's largest entry (the default 0.001 took
        // near-zero multiplier diagonals and lost all accuracy).
        static std::array<double, UMFPACK_CONTROL>
        make_control()
        {
          std::array<double, UMFPACK_CONTROL> control;
          umfpack_dl_defaults(control.data());
          control[UMFPACK_STRATEGY]            = UMFPACK_STRATEGY_SYMMETRIC;
          control[UMFPACK_ORDERING]            = UMFPACK_ORDERING_AMD;
          control[UMFPACK_SYM_PIVOT_TOLERANCE] = 0.1;
          return control;
        }

        const std::array<double, UMFPACK_CONTROL> control = make_control();
        double                                    reciprocal_condition = 1.;
        void                                     *symbolic = nullptr;
        void                                     *numeric  = nullptr;
        std::vector<SuiteSparse_long>             row_start, column_index;
        std::vector<double>                       values;
        // Storage position of the k-th entry of the deal.II matrix.
        std::vector<std::size_t> position;
      };
    } // namespace


    struct LinearSolver::Implementation
    {
      // Factorises `matrix` with the chosen package; back_substitute() then
      // solves with it for any number of right-hand sides.
      void
      factorize(const std::string &type, const SparseMatrix<double> &matrix);
      void
      back_substitute(const Vector<double> &rhs, Vector<double> &solution);

      std::string                           type;
      UmfpackFactorization                  umfpack;
      TrilinosWrappers::SparseMatrix        trilinos_matrix;
      std::unique_ptr<Epetra_Vector>        epetra_rhs, epetra_solution;
      std::unique_ptr<Epetra_LinearProblem> epetra_problem;
      std::unique_ptr<Amesos_BaseSolver>    amesos;

      // The matrix without the bordered unknowns: its pattern is rebuilt
      // only when the full pattern or the bordered set changes.
      const SparsityPattern               *full_pattern  = nullptr;
      std::size_t                          full_nonzeros = 0;
      std::vector<types::global_dof_index> bordered_of_pattern;
      std::vector<types::global_dof_index> reduced_index;
      SparsityPattern                      reduced_pattern;
      SparseMatrix<double>                 reduced_matrix;
    };


    void
    LinearSolver::Implementation::factorize(const std::string          &type,
                                            const SparseMatrix<double> &matrix)
    {
      this->type = type;
      if (type == "UMFPACK")
      {
        umfpack.factorize(matrix);
        return;
      }
      // Amesos directly rather than through TrilinosWrappers::SolverDirect:
      // MUMPS needs more working space than its default estimate (ICNTL(14),
      // in percent) when zero diagonals of the contact rows delay pivots.
      // The old solver refers to the old problem and matrix: release it
      // first.
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
      if (type == "MUMPS")
      {
        auto mumps = std::make_unique<Amesos_Mumps>(*epetra_problem);
        mumps->SetICNTL(14, 400);
        amesos = std::move(mumps);
      }
      else
        amesos = std::make_unique<Amesos_Klu>(*epetra_problem);
      if (amesos->SymbolicFactorization() != 0
          || amesos->NumericFactorization() != 0)
      {
        std::string detail;
        if (auto *mumps = dynamic_cast<Amesos_Mumps *>(amesos.get()))
          detail = " (MUMPS INFOG(1) = " + std::to_string(mumps->GetINFOG()[0])
                   + ", INFOG(2) = " + std::to_string(mumps->GetINFOG()[1])
                   + ")";
        throw std::runtime_error("Amesos " + type
                                 + " could not factorise the matrix" + detail);
      }
    }


    void
    LinearSolver::Implementation::back_substitute(const Vector<double> &rhs,
                                                  Vector<double> &solution)
    {
      solution.reinit(rhs.size());
      if (type == "UMFPACK")
      {
        umfpack.solve(rhs, solution);
        return;
      }
      for (unsigned int i = 0; i < rhs.size(); ++i)
        (*epetra_rhs)[i] = rhs[i];
      if (amesos->Solve() != 0)
        throw std::runtime_error("Amesos " + type + " could not solve");
      for (unsigned int i = 0; i < solution.size(); ++i)
        solution[i] = (*epetra_solution)[i];
    }


    LinearSolver::LinearSolver(const LinearSolverParameters &parameters)
        : parameters(parameters)
        , implementation(std::make_unique<Implementation>())
    {
    }


    LinearSolver::~LinearSolver() = default;


    void
    LinearSolver::solve(const SparseMatrix<double>                 &matrix,
                        const Vector<double>                       &rhs,
                        Vector<double>                             &solution,
                        const std::vector<types::global_dof_index> &bordered)
    {
      try
      {
        if (bordered.empty())
        {
          implementation->factorize(parameters.type, matrix);
          implementation->back_substitute(rhs, solution);
          return;
        }

        Implementation               &data    = *implementation;
        const SparsityPattern        &pattern = matrix.get_sparsity_pattern();
        const types::global_dof_index n       = matrix.m();
        const unsigned int            n_b     = bordered.size();
        if (data.full_pattern != &pattern
            || data.full_nonzeros != pattern.n_nonzero_elements()
            || data.bordered_of_pattern != bordered)
        {
          data.full_pattern        = &pattern;
          data.full_nonzeros       = pattern.n_nonzero_elements();
          data.bordered_of_pattern = bordered;
          data.reduced_index.assign(n, 0);
          for (const auto dof : bordered)
            data.reduced_index[dof] = numbers::invalid_dof_index;
          types::global_dof_index next = 0;
          for (auto &index : data.reduced_index)
            if (index != numbers::invalid_dof_index)
              index = next++;
          DynamicSparsityPattern dsp(next, next);
          for (types::global_dof_index i = 0; i < n; ++i)
            if (data.reduced_index[i] != numbers::invalid_dof_index)
              for (auto entry = pattern.begin(i); entry != pattern.end(i);
                   ++entry)
                if (data.reduced_index[entry->column()]
                    != numbers::invalid_dof_index)
                  dsp.add(data.reduced_index[i],
                          data.reduced_index[entry->column()]);
          data.reduced_pattern.copy_from(dsp);
          data.reduced_matrix.reinit(data.reduced_pattern);
        }

        // A = [M C; D E] in the bordered unknowns b (columns of C, rows of
        // D) and the rest.
        const types::global_dof_index n_m = data.reduced_pattern.n_rows();
        std::vector<Vector<double>>   columns(n_b, Vector<double>(n_m));
        std::vector<Vector<double>>   rows(n_b, Vector<double>(n_m));
        FullMatrix<double>            corner(n_b, n_b);
        std::vector<int>              border_position(n, -1);
        for (unsigned int k = 0; k < n_b; ++k)
          border_position[bordered[k]] = k;
        // The reduced rows keep the order of the full rows (diagonal first,
        // then ascending columns, and the renumbering is monotone): copy in
        // step instead of searching each entry.
        for (types::global_dof_index i = 0; i < n; ++i)
        {
          const int bi = border_position[i];
          auto      reduced_entry
            = bi < 0 ? data.reduced_matrix.begin(data.reduced_index[i])
                     : data.reduced_matrix.end();
          for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
          {
            const auto   j     = entry->column();
            const double value = entry->value();
            const int    bj    = border_position[j];
            if (bi < 0 && bj < 0)
            {
              AssertThrow(reduced_entry->column() == data.reduced_index[j],
                          ExcInternalError());
              reduced_entry->value() = value;
              ++reduced_entry;
            }
            else if (bi < 0)
              columns[bj][data.reduced_index[i]] = value;
            else if (bj < 0)
              rows[bi][data.reduced_index[j]] = value;
            else
              corner(bi, bj) = value;
          }
        }

        data.factorize(parameters.type, data.reduced_matrix);
        Vector<double> reduced_rhs(n_m), y(n_m);
        for (types::global_dof_index i = 0; i < n; ++i)
          if (border_position[i] < 0)
            reduced_rhs[data.reduced_index[i]] = rhs[i];
        data.back_substitute(reduced_rhs, y);
        // S = E - D M^-1 C, z = S^-1 (f_b - D M^-1 f), x = M^-1 f - M^-1 C z.
        std::vector<Vector<double>> inverse_columns(n_b);
        FullMatrix<double>          schur(corner);
        Vector<double>              border_rhs(n_b), z(n_b);
        for (unsigned int k = 0; k < n_b; ++k)
        {
          data.back_substitute(columns[k], inverse_columns[k]);
          border_rhs[k] = rhs[bordered[k]] - rows[k] * y;
        }
        for (unsigned int k = 0; k < n_b; ++k)
          for (unsigned int l = 0; l < n_b; ++l)
            schur(k, l) -= rows[k] * inverse_columns[l];
        schur.gauss_jordan();
        schur.vmult(z, border_rhs);
        for (unsigned int k = 0; k < n_b; ++k)
          y.add(-z[k], inverse_columns[k]);
        solution.reinit(n);
        for (types::global_dof_index i = 0; i < n; ++i)
          solution[i] = border_position[i] < 0 ? y[data.reduced_index[i]]
                                               : z[border_position[i]];
      }
      catch (const std::exception &error)
      {
        throw std::runtime_error(
          "the linear solver (" + parameters.type
          + ") failed; the stiffness matrix is probably singular (are "
            "rigid-body motions prevented by the boundary conditions?): "
          + error.what());
      }
    }
  } // namespace solver
} // namespace deepdraw
