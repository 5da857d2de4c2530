// The serial Newton system (linear_algebra/newton_linear_system.h, D100): a
// deal.II SparseMatrix over the whole pattern, cell matrices added through
// the positions of their entries in the matrix's values (D99), solved by
// solver::LinearSolver.
#include <algorithm>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deepdraw/linear_algebra/newton_linear_system.h>
#include <deepdraw/parallel/ranks.h>
#include <limits>

namespace deepdraw
{
  namespace linear_algebra
  {
    namespace
    {
      class SerialNewtonSystem : public NewtonLinearSystem, public SystemMatrix
      {
      public:
        explicit SerialNewtonSystem(
          const solver::LinearSolverParameters &parameters)
            : iterative(parameters.iterative())
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
        reset_reduction() override
        {
          linear_solver.reset_reduction();
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
          if (system_matrix.n_nonzero_elements() > 0)
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
        // cell_matrix_positions for the dofs of the layout.
        void
        find_cell_matrix_positions(const DoFHandler<3> &dof_handler);
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
        unsigned int              dofs_per_cell = 0;
        const DoFHandler<3>      *dof_handler   = nullptr;
        // Type AMG: the component of each displacement unknown.
        std::vector<unsigned char> components;
        const bool                 iterative;
        bool                       rigid_body_modes_stale = true;
        solver::LinearSolver       linear_solver;
      };


      void
      SerialNewtonSystem::update_rigid_body_modes()
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
      SerialNewtonSystem::reinit(const SystemLayout &layout)
      {
        const DoFHandler<3>          &dof_handler = *layout.dof_handler;
        const types::global_dof_index n_u         = dof_handler.n_dofs();
        this->dof_handler                         = &dof_handler;
        rigid_body_modes_stale                    = true;
        components.clear();
        const types::global_dof_index n = layout.n_unknowns;
        // Contact unknowns follow the displacements (block system of
        // reference Eq. 19).
        DynamicSparsityPattern displacement_dsp(n_u, n_u);
        DoFTools::make_sparsity_pattern(dof_handler,
                                        displacement_dsp,
                                        *layout.constraints,
                                        /*keep_constrained_dofs=*/true);
        DynamicSparsityPattern dsp(n, n);
        for (types::global_dof_index row = 0; row < n_u; ++row)
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
                                            constrained);
        system_rhs.reinit(n);
      }


      void
      SerialNewtonSystem::find_cell_matrix_positions(
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
        cell_matrix_positions.resize(
          std::size_t(dof_handler.get_triangulation().n_active_cells()) * n
          * n);
        std::vector<types::global_dof_index> dofs(n);
        for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          unsigned int *positions
            = &cell_matrix_positions[std::size_t(cell->active_cell_index()) * n
                                     * n];
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
      SerialNewtonSystem::add_cell_matrix(const unsigned int active_cell_index,
                                          const FullMatrix<double> &cell_matrix)
      {
        // Each entry gets the one addition that
        // AffineConstraints::distribute_local_to_global would make, in the
        // same order, so the sums are the same to the last bit (D98, D99).
        const unsigned int  n = dofs_per_cell;
        const unsigned int *positions
          = &cell_matrix_positions[std::size_t(active_cell_index) * n * n];
        double       *values = const_cast<double *>(&system_matrix(0, 0));
        const double *local  = &cell_matrix(0, 0);
        for (unsigned int k = 0; k < n * n; ++k)
          values[positions[k]] += local[k];
      }


      void
      SerialNewtonSystem::copy_to(FullMatrix<double> &full) const
      {
        full.reinit(system_matrix.m(), system_matrix.n());
        for (unsigned int i = 0; i < system_matrix.m(); ++i)
          for (auto entry = system_matrix.begin(i);
               entry != system_matrix.end(i);
               ++entry)
            full(i, entry->column()) = entry->value();
      }
    } // namespace


    std::unique_ptr<NewtonLinearSystem>
    make_serial_system(const solver::LinearSolverParameters &parameters)
    {
      return std::make_unique<SerialNewtonSystem>(parameters);
    }
  } // namespace linear_algebra
} // namespace deepdraw
