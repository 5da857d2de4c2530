#include <Amesos_Klu.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_Vector.h>
#include <algorithm>
#include <array>
#include <deal.II/base/parallel.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deepdraw/solver/linear_solver.h>
#include <deepdraw/solver/mumps_factorization.h>
#include <deepdraw/solver/umfpack_factorization.h>
#include <mutex>
#include <stdexcept>

namespace deepdraw
{
  namespace solver
  {
    void
    LinearSolverParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.declare_entry("Type",
                        "MUMPS",
                        Patterns::Selection("UMFPACK|MUMPS|KLU"),
                        "Direct solver of the Newton system: MUMPS "
                        "(multifrontal LU, called directly; 10-15 % faster "
                        "than UMFPACK on the square-cup meshes, "
                        "doc/decisions.md D96), UMFPACK (SuiteSparse, "
                        "called directly) or KLU (through Trilinos Amesos).");
      prm.declare_entry("Leave out decoupled unknowns",
                        "false",
                        Patterns::Bool(),
                        "Factorise the Newton matrix without the unknowns "
                        "whose row and column hold only the diagonal: the "
                        "contact forces of open pairs and the constrained "
                        "dofs (the same solution, a smaller system, but a "
                        "worse fill-reducing ordering and a new analysis "
                        "whenever the open set changes: 13 % slower on the "
                        "square cup; doc/decisions.md D60, D64). Applies "
                        "to the whole system only: with Condense contact "
                        "multipliers it is used for the solves that fall "
                        "back to the whole system.");
      prm.declare_entry(
        "Condense contact multipliers",
        "true",
        Patterns::Bool(),
        "Eliminate the contact forces exactly before the factorisation: "
        "the factorised matrix has the displacements only, bordered by the "
        "positions of force-controlled tools, and the Newton step is the "
        "same (doc/decisions.md D90). Nodes touching two tools at once "
        "fall back to the whole system for that solve.");
      prm.leave_subsection();
    }


    void
    LinearSolverParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      type                 = prm.get("Type");
      leave_out_decoupled  = prm.get_bool("Leave out decoupled unknowns");
      condense_multipliers = prm.get_bool("Condense contact multipliers");
      prm.leave_subsection();
    }


    struct LinearSolver::Implementation
    {
      // Factorises `matrix` with the chosen package; back_substitute() then
      // solves with it for any number of right-hand sides.
      void
      factorize(const std::string &type, const SparseMatrix<double> &matrix);
      void
      back_substitute(const Vector<double> &rhs, Vector<double> &solution);
      // Solves for each column in place (MUMPS: one pass through the
      // factors for all of them).
      void
      back_substitute(std::vector<Vector<double>> &columns);

      std::string type;
      // MUMPS scales rows and columns (the whole system, whose multiplier
      // rows are scaled unlike the displacements); not the condensed one.
      bool                 scale_matrix = true;
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
      std::vector<int>                     border_position;
      SparsityPattern                      reduced_pattern;
      SparseMatrix<double>                 reduced_matrix;
      // A = [M C; D E] in the bordered unknowns b (columns of C, rows of D).
      std::vector<Vector<double>> border_columns, border_rows;
      FullMatrix<double>          corner;
      LinearSolver::Statistics    statistics;
      bool                        reduction_reset = false;
      // Unknowns the current reduction leaves out.
      types::global_dof_index n_left_out = 0;
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
      if (type == "MUMPS")
      {
        if (mumps == nullptr)
          mumps = std::make_unique<MumpsFactorization>(scale_matrix);
        mumps->factorize(matrix);
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
    LinearSolver::Implementation::back_substitute(const Vector<double> &rhs,
                                                  Vector<double> &solution)
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
    LinearSolver::Implementation::back_substitute(
      std::vector<Vector<double>> &columns)
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
    LinearSolver::Implementation::update_reduction(
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
    LinearSolver::Implementation::build_reduction(
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
      types::global_dof_index n_m = 0;
      for (types::global_dof_index i = 0; i < n; ++i)
        if (role[i] == kept)
          reduced_index[i] = n_m++;

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


    bool
    LinearSolver::Implementation::copy_reduced(
      const SparseMatrix<double> &matrix)
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
      parallel::apply_to_subranges(
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
        return true;
      // Not decoupled after all: keep these from now on.
      for (const auto j : coupled)
        is_decoupled[j] = false;
      build_reduction(*full_pattern, bordered_of_pattern);
      return false;
    }


    void
    LinearSolver::Implementation::copy_reduced_rows(
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


    LinearSolver::LinearSolver(const LinearSolverParameters &parameters)
        : parameters(parameters)
        , implementation(std::make_unique<Implementation>())
        , condensed_implementation(std::make_unique<Implementation>())
    {
      // Displacements only, in N/mm throughout: well scaled (D98).
      condensed_implementation->scale_matrix = false;
    }


    LinearSolver::~LinearSolver() = default;


    void
    LinearSolver::reset_reduction()
    {
      for (Implementation *data :
           {implementation.get(), condensed_implementation.get()})
      {
        data->reduction_reset = true;
        data->umfpack.forget_analysis();
      }
    }


    LinearSolver::Statistics
    LinearSolver::statistics() const
    {
      // Both systems together (the condensed one and the whole one).
      Statistics total = solve_statistics;
      for (const Implementation *data :
           {implementation.get(), condensed_implementation.get()})
      {
        total.factorizations += data->statistics.factorizations;
        total.reductions += data->statistics.reductions;
        total.numeric_factorizations += data->statistics.numeric_factorizations;
        total.symbolic_analyses += data->umfpack.n_symbolic_analyses();
        if (data->mumps != nullptr)
          total.symbolic_analyses += data->mumps->n_symbolic_analyses();
      }
      return total;
    }


    void
    LinearSolver::set_multiplier_blocks(
      const SparsityPattern                      &pattern,
      const types::global_dof_index               n_displacements,
      const std::vector<MultiplierBlock>         &blocks,
      const std::vector<types::global_dof_index> &tool_positions,
      const std::vector<bool>                    &constrained)
    {
      if (!parameters.condense_multipliers || blocks.empty())
      {
        condensation.reset();
        return;
      }
      condensation = std::make_unique<MultiplierCondensation>();
      // A new condensed pattern, possibly at the old one's address.
      condensed_implementation->full_pattern = nullptr;
      condensation->initialize(pattern,
                               n_displacements,
                               blocks,
                               tool_positions,
                               constrained);
    }


    void
    LinearSolver::solve(const SparseMatrix<double>                 &matrix,
                        const Vector<double>                       &rhs,
                        Vector<double>                             &solution,
                        const std::vector<types::global_dof_index> &bordered,
                        const std::vector<types::global_dof_index> &decoupled)
    {
      solve_statistics.unknowns = matrix.m();
      if (condensation != nullptr && condensation->condense(matrix, rhs))
      {
        // The multipliers eliminated exactly (D90): the factorised matrix
        // is the displacement block, bordered by the tool positions.
        Implementation &condensed = *condensed_implementation;
        Vector<double>  condensed_solution;
        solve_with(condensed,
                   condensation->matrix(),
                   condensation->rhs(),
                   condensed_solution,
                   condensation->condensed_tool_positions(),
                   {});
        condensation->expand(matrix, rhs, condensed_solution, solution);
        ++solve_statistics.condensed_solves;
        solve_statistics.factorized_unknowns
          = condensed.statistics.factorized_unknowns;
        return;
      }
      solve_with(*implementation, matrix, rhs, solution, bordered, decoupled);
      solve_statistics.factorized_unknowns
        = implementation->statistics.factorized_unknowns;
    }


    void
    LinearSolver::solve_with(
      Implementation                             &data,
      const SparseMatrix<double>                 &matrix,
      const Vector<double>                       &rhs,
      Vector<double>                             &solution,
      const std::vector<types::global_dof_index> &bordered,
      const std::vector<types::global_dof_index> &decoupled)
    {
      const types::global_dof_index n = matrix.m();
      ++data.statistics.factorizations;
      data.statistics.unknowns = n;
      try
      {
        if (bordered.empty() && decoupled.empty())
        {
          data.statistics.factorized_unknowns = n;
          data.factorize(parameters.type, matrix);
          ++data.statistics.numeric_factorizations;
          data.back_substitute(rhs, solution);
          return;
        }

        data.update_reduction(matrix.get_sparsity_pattern(),
                              bordered,
                              decoupled);
        while (!data.copy_reduced(matrix))
        {
        }
        const types::global_dof_index n_m   = data.reduced_pattern.n_rows();
        const unsigned int            n_b   = bordered.size();
        data.statistics.factorized_unknowns = n_m;
        data.factorize(parameters.type, data.reduced_matrix);
        ++data.statistics.numeric_factorizations;
        // columns: f, then C (the border columns); M^-1 of all at once.
        std::vector<Vector<double>> columns(1, Vector<double>(n_m));
        for (types::global_dof_index i = 0; i < n; ++i)
          if (data.role[i] == Implementation::kept)
            columns[0][data.reduced_index[i]] = rhs[i];
        columns.insert(columns.end(),
                       data.border_columns.begin(),
                       data.border_columns.end());
        data.back_substitute(columns);
        Vector<double> y, z(n_b);
        y.swap(columns[0]);
        // S = E - D M^-1 C, z = S^-1 (f_b - D M^-1 f), x = M^-1 f - M^-1 C z.
        if (n_b > 0)
        {
          // M^-1 C, column by column.
          const Vector<double> *inverse_columns = columns.data() + 1;
          FullMatrix<double>    schur(data.corner);
          Vector<double>        border_rhs(n_b);
          for (unsigned int k = 0; k < n_b; ++k)
            border_rhs[k] = rhs[bordered[k]] - data.border_rows[k] * y;
          for (unsigned int k = 0; k < n_b; ++k)
            for (unsigned int l = 0; l < n_b; ++l)
              schur(k, l) -= data.border_rows[k] * inverse_columns[l];
          schur.gauss_jordan();
          schur.vmult(z, border_rhs);
          for (unsigned int k = 0; k < n_b; ++k)
            y.add(-z[k], inverse_columns[k]);
        }
        // A decoupled unknown's row is its diagonal alone.
        solution.reinit(n);
        for (types::global_dof_index i = 0; i < n; ++i)
          switch (data.role[i])
          {
            case Implementation::kept:
              solution[i] = y[data.reduced_index[i]];
              break;
            case Implementation::bordered:
              solution[i] = z[data.border_position[i]];
              break;
            case Implementation::left_out:
              solution[i] = rhs[i] / matrix.diag_element(i);
              break;
          }
      }
      catch (const MumpsMemoryError &)
      {
        throw; // not the matrix (D177)
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
