// The Newton system (linear_algebra/newton_linear_system.h, D100): a deal.II
// SparseMatrix, cell matrices added through the positions of their entries
// in the matrix's values (D99), solved by solver::LinearSolver. Serial: the
// whole pattern. Split by rows (D214): each rank stores the rows it holds
// (RowPartition) and completes those it owns.
#include <algorithm>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deepdraw/linear_algebra/newton_linear_system.h>
#include <deepdraw/linear_algebra/row_partition.h>
#include <deepdraw/parallel/cell_partition.h>
#include <deepdraw/parallel/ranks.h>
#include <limits>

namespace deepdraw
{
  namespace linear_algebra
  {
    namespace
    {
      class SparseNewtonSystem : public NewtonLinearSystem, public SystemMatrix
      {
      public:
        SparseNewtonSystem(const solver::LinearSolverParameters &parameters,
                           const bool                            split_by_rows)
            : split_by_rows(split_by_rows)
            , iterative(parameters.iterative())
            , linear_solver(parameters)
        {
        }

        void
        reinit(const SystemLayout &layout) override;

        void
        zero(const bool with_matrix) override
        {
          if (with_matrix)
            system_matrix = 0.;
          system_rhs = 0.;
        }

        SystemMatrix &
        matrix() override
        {
          return *this;
        }

        Vector &
        rhs() override
        {
          return system_rhs;
        }

        const Vector &
        rhs() const override
        {
          return system_rhs;
        }

        void
        solve(Vector                                     &solution,
              const std::vector<types::global_dof_index> &bordered,
              const std::vector<types::global_dof_index> &decoupled) override
        {
          if (iterative && rigid_body_modes_stale)
            update_rigid_body_modes();
          linear_solver.solve(system_matrix,
                              system_rhs,
                              solution,
                              bordered,
                              decoupled);
        }

        void
        reset_reduction(const bool continues_stage) override
        {
          linear_solver.reset_reduction(continues_stage);
          // The mesh moves between increments (updated Lagrangian).
          rigid_body_modes_stale = true;
        }

        solver::LinearSolver::Statistics
        statistics() const override
        {
          return linear_solver.statistics();
        }

        void
        copy_to(FullMatrix<double> &full) const override;

        // SystemMatrix
        void
        add_cell_matrix(unsigned int              active_cell_index,
                        const FullMatrix<double> &cell_matrix) override;

        void
        add_local(const AffineConstraints<double>            &constraints,
                  const FullMatrix<double>                   &local_matrix,
                  const Vector                               &local_rhs,
                  const std::vector<types::global_dof_index> &dofs,
                  Vector                                     &rhs) override
        {
          if (rows != nullptr && !holds_every_row(constraints, dofs))
          {
            add_to_held_rows(constraints, local_matrix, local_rhs, dofs, rhs);
            return;
          }
          // distribute_local_to_global finds each entry by walking its row
          // from the start: a contact pair of a force-controlled tool adds
          // to the tool's row, which holds every pair of the tool, so that
          // walk made the contact assembly quadratic in the pairs (D211).
          // Without constraints, the same additions with a binary search.
          if (std::any_of(dofs.begin(),
                          dofs.end(),
                          [&](const types::global_dof_index dof)
                          { return constraints.is_constrained(dof); }))
          {
            constraints.distribute_local_to_global(local_matrix,
                                                   local_rhs,
                                                   dofs,
                                                   system_matrix,
                                                   rhs);
            return;
          }
          for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            for (unsigned int j = 0; j < dofs.size(); ++j)
              if (local_matrix(i, j) != 0.)
                system_matrix.add(dofs[i], dofs[j], local_matrix(i, j));
            rhs(dofs[i]) += local_rhs(i);
          }
        }

        void
        sum_over_ranks() override
        {
          if (rows != nullptr)
            send_rows_to_owners();
          else if (system_matrix.n_nonzero_elements() > 0)
            parallel::sum(const_cast<double *>(&system_matrix(0, 0)),
                          system_matrix.n_nonzero_elements());
        }

        void
        add(const types::global_dof_index row,
            const types::global_dof_index column,
            const double                  value) override
        {
          system_matrix.add(row, column, value);
        }

      private:
        // Split by rows: whether every row the local matrix adds to
        // through the constraints is held here.
        bool
        holds_every_row(const AffineConstraints<double>            &constraints,
                        const std::vector<types::global_dof_index> &dofs) const;
        // A contact pair whose node this rank does not hold: the
        // right-hand side whole, the matrix into the held rows (the tool's).
        void
        add_to_held_rows(const AffineConstraints<double> &constraints,
                         const FullMatrix<double>        &local_matrix,
                         const Vector                    &local_rhs,
                         const std::vector<types::global_dof_index> &dofs,
                         Vector                                     &rhs);
        // After the element loop: each displacement row held here and owned
        // elsewhere is added into its owner's (D214).
        void
        send_rows_to_owners();
        // cell_matrix_positions for the dofs of the layout.
        void
        find_cell_matrix_positions(const DoFHandler<3> &dof_handler);
        unsigned int
        slot(const unsigned int active_cell_index) const
        {
          return cell_slot.empty() ? active_cell_index
                                   : cell_slot[active_cell_index];
        }
        // Type AMG: the support points of the displacement unknowns in the
        // mesh's current configuration, for the rigid-body modes (D193).
        void
        update_rigid_body_modes();

        SparsityPattern      sparsity_pattern;
        SparseMatrix<double> system_matrix;
        Vector               system_rhs;
        // Per active cell, where the entries of its 24 x 24 matrix
        // (row-major, local order) lie in system_matrix's values: cells
        // are added through them instead of searching the rows (D99).
        // Rebuilt with the sparsity pattern.
        std::vector<unsigned int> cell_matrix_positions;
        // Under mpirun, the place in cell_matrix_positions of each of this
        // rank's cells, by active cell index (empty when serial: all cells
        // in their order).
        std::vector<unsigned int> cell_slot;
        unsigned int              dofs_per_cell = 0;
        const DoFHandler<3>      *dof_handler   = nullptr;
        // Type AMG: the component of each displacement unknown.
        std::vector<unsigned char>    components;
        const bool                    split_by_rows;
        std::unique_ptr<RowPartition> rows;
        const bool                    iterative;
        bool                          rigid_body_modes_stale = true;
        solver::LinearSolver          linear_solver;
      };


      void
      SparseNewtonSystem::update_rigid_body_modes()
      {
        // The components depend on the numbering alone: found once per
        // layout, the points once per increment.
        if (components.size() != dof_handler->n_dofs())
        {
          components.resize(dof_handler->n_dofs());
          std::vector<types::global_dof_index> dofs(dofs_per_cell);
          for (const auto &cell : dof_handler->active_cell_iterators())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              components[dofs[i]]
                = dof_handler->get_fe().system_to_component_index(i).first;
          }
        }
        std::vector<Point<3>> points(dof_handler->n_dofs());
        DoFTools::map_dofs_to_support_points(MappingQ1<3>(),
                                             *dof_handler,
                                             points);
        linear_solver.set_rigid_body_modes(points, components);
        rigid_body_modes_stale = false;
      }


      void
      SparseNewtonSystem::reinit(const SystemLayout &layout)
      {
        const DoFHandler<3>          &dof_handler = *layout.dof_handler;
        const types::global_dof_index n_u         = dof_handler.n_dofs();
        this->dof_handler                         = &dof_handler;
        rigid_body_modes_stale                    = true;
        components.clear();
        const types::global_dof_index n = layout.n_unknowns;
        // An empty row set: every row (DynamicSparsityPattern).
        IndexSet held_rows, held_displacements;
        if (split_by_rows)
        {
          rows               = std::make_unique<RowPartition>(dof_handler,
                                                *layout.constraints,
                                                n,
                                                layout.multiplier_blocks);
          held_rows          = rows->held_rows();
          held_displacements = held_rows.get_view(0, n_u);
        }
        // Contact unknowns follow the displacements (block system of
        // reference Eq. 19). Rows not held keep their diagonal only.
        DynamicSparsityPattern displacement_dsp(n_u, n_u, held_displacements);
        DoFTools::make_sparsity_pattern(dof_handler,
                                        displacement_dsp,
                                        *layout.constraints,
                                        /*keep_constrained_dofs=*/true);
        DynamicSparsityPattern dsp(n, n, held_rows);
        for (types::global_dof_index row = 0; row < n_u; ++row)
          if (rows == nullptr || rows->holds(row))
            for (auto entry = displacement_dsp.begin(row);
                 entry != displacement_dsp.end(row);
                 ++entry)
              dsp.add(row, entry->column());
        if (layout.add_contact_couplings)
          layout.add_contact_couplings(dsp);
        sparsity_pattern.copy_from(dsp);
        system_matrix.reinit(sparsity_pattern);
        dofs_per_cell = dof_handler.get_fe().n_dofs_per_cell();
        find_cell_matrix_positions(dof_handler);
        std::vector<bool> constrained(n, false);
        for (const auto &line : layout.constraints->get_lines())
          constrained[line.index] = true;
        linear_solver.set_multiplier_blocks(sparsity_pattern,
                                            n_u,
                                            layout.multiplier_blocks,
                                            layout.tool_positions,
                                            constrained,
                                            rows == nullptr
                                              ? std::vector<bool>()
                                              : rows->owned_rows());
        system_rhs.reinit(n);
      }


      void
      SparseNewtonSystem::find_cell_matrix_positions(
        const DoFHandler<3> &dof_handler)
      {
        const unsigned int n = dofs_per_cell;
        AssertThrow(sparsity_pattern.n_nonzero_elements()
                      < std::numeric_limits<unsigned int>::max(),
                    ExcMessage("more matrix entries than unsigned int holds"));
        // add_cell_matrix starts at the entry (0, 0): a square compressed
        // pattern stores each row's diagonal first.
        AssertThrow(sparsity_pattern.n_rows() == 0
                      || sparsity_pattern(0, 0) == 0,
                    ExcInternalError());
        // This rank's cells only (all of them when serial).
        const auto &mesh = dof_handler.get_triangulation();
        cell_slot.clear();
        unsigned int n_cells = mesh.n_active_cells();
        if (rows != nullptr)
        {
          cell_slot.assign(mesh.n_active_cells(),
                           numbers::invalid_unsigned_int);
          n_cells = 0;
          for (const auto &cell : mesh.active_cell_iterators())
            if (parallel::is_owned(*cell))
              cell_slot[cell->active_cell_index()] = n_cells++;
        }
        cell_matrix_positions.resize(std::size_t(n_cells) * n * n);
        std::vector<types::global_dof_index> dofs(n);
        for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (rows != nullptr && !parallel::is_owned(*cell))
            continue;
          cell->get_dof_indices(dofs);
          unsigned int *positions
            = &cell_matrix_positions[std::size_t(
                                       slot(cell->active_cell_index()))
                                     * n * n];
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
            {
              const std::size_t position = sparsity_pattern(dofs[i], dofs[j]);
              AssertThrow(position != SparsityPattern::invalid_entry,
                          ExcInternalError());
              positions[i * n + j] = position;
            }
        }
      }


      void
      SparseNewtonSystem::add_cell_matrix(const unsigned int active_cell_index,
                                          const FullMatrix<double> &cell_matrix)
      {
        // Each entry gets the one addition that
        // AffineConstraints::distribute_local_to_global would make, in the
        // same order, so the sums are the same to the last bit (D98, D99).
        const unsigned int  n = dofs_per_cell;
        const unsigned int *positions
          = &cell_matrix_positions[std::size_t(slot(active_cell_index)) * n
                                   * n];
        double       *values = const_cast<double *>(&system_matrix(0, 0));
        const double *local  = &cell_matrix(0, 0);
        for (unsigned int k = 0; k < n * n; ++k)
          values[positions[k]] += local[k];
      }


      bool
      SparseNewtonSystem::holds_every_row(
        const AffineConstraints<double>            &constraints,
        const std::vector<types::global_dof_index> &dofs) const
      {
        for (const auto dof : dofs)
        {
          if (!rows->holds(dof))
            return false;
          if (const auto *entries = constraints.get_constraint_entries(dof))
            for (const auto &entry : *entries)
              if (!rows->holds(entry.first))
                return false;
        }
        return true;
      }


      void
      SparseNewtonSystem::add_to_held_rows(
        const AffineConstraints<double>            &constraints,
        const FullMatrix<double>                   &local_matrix,
        const Vector                               &local_rhs,
        const std::vector<types::global_dof_index> &dofs,
        Vector                                     &rhs)
      {
        // Every rank adds the whole right-hand side, as on one rank. The
        // pairs whose rows are held only in part are those of a node no
        // constraint touches (RowPartition holds constrained nodes
        // everywhere): its constrained unknowns are fixed multipliers,
        // whose rows and columns distribute_local_to_global leaves out.
        constraints.distribute_local_to_global(local_rhs, dofs, rhs);
        for (const auto dof : dofs)
          AssertThrow(!constraints.is_constrained(dof)
                        || (constraints.get_constraint_entries(dof)->empty()
                            && constraints.get_inhomogeneity(dof) == 0.),
                      ExcMessage("a contact pair at a constrained node "
                                 "whose rows this rank does not hold"));
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (rows->holds(dofs[i]) && !constraints.is_constrained(dofs[i]))
            for (unsigned int j = 0; j < dofs.size(); ++j)
              if (local_matrix(i, j) != 0.
                  && !constraints.is_constrained(dofs[j]))
                system_matrix.add(dofs[i], dofs[j], local_matrix(i, j));
      }


      void
      SparseNewtonSystem::send_rows_to_owners()
      {
        const unsigned int               n_ranks = parallel::n_ranks();
        std::vector<std::vector<double>> to_rank(n_ranks), from_rank;
        for (unsigned int r = 0; r < n_ranks; ++r)
          for (const auto row : rows->rows_to_send()[r])
            for (auto entry = system_matrix.begin(row);
                 entry != system_matrix.end(row);
                 ++entry)
              to_rank[r].push_back(entry->value());
        parallel::exchange(to_rank, from_rank);
        // In the ranks' order: the same sums whatever the timing.
        for (unsigned int r = 0; r < n_ranks; ++r)
        {
          std::size_t k = 0;
          for (const auto row : rows->rows_to_receive()[r])
            for (auto entry = system_matrix.begin(row);
                 entry != system_matrix.end(row);
                 ++entry)
              entry->value() += from_rank[r].at(k++);
          AssertThrow(k == from_rank[r].size(), ExcInternalError());
        }
      }


      void
      SparseNewtonSystem::copy_to(FullMatrix<double> &full) const
      {
        full.reinit(system_matrix.m(), system_matrix.n());
        for (unsigned int i = 0; i < system_matrix.m(); ++i)
          if (rows == nullptr || rows->owns(i))
            for (auto entry = system_matrix.begin(i);
                 entry != system_matrix.end(i);
                 ++entry)
              full(i, entry->column()) = entry->value();
      }
    } // namespace


    std::unique_ptr<NewtonLinearSystem>
    make_serial_system(const solver::LinearSolverParameters &parameters)
    {
      return std::make_unique<SparseNewtonSystem>(parameters, false);
    }


    std::unique_ptr<NewtonLinearSystem>
    make_system(const solver::LinearSolverParameters &parameters)
    {
      return std::make_unique<SparseNewtonSystem>(parameters,
                                                  parallel::n_ranks() > 1);
    }
  } // namespace linear_algebra
} // namespace deepdraw
