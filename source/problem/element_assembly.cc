#include <algorithm>
#include <atomic>
#include <deal.II/base/work_stream.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/parallel/cell_partition.h>
#include <deepdraw/problem/element_assembly.h>

namespace deepdraw
{
  namespace problem
  {
    namespace
    {
      struct AssemblyScratch
      {
        // Stands in for the enhanced parameters of elements without any.
        fe::EnhancedParameters no_enhanced_parameters;
      };

      struct AssemblyCopy
      {
        FullMatrix<double> matrix
          = FullMatrix<double>(fe::dofs_per_cell, fe::dofs_per_cell);
        Vector<double> residual = Vector<double>(fe::dofs_per_cell);
        std::vector<types::global_dof_index> dofs
          = std::vector<types::global_dof_index>(fe::dofs_per_cell);
        unsigned int cell_index = 0;
        bool         active     = false;
      };
    } // namespace


    ElementAssemblyResult
    assemble_elements(const fe::HexahedronElement               &element,
                      const discretisation::SheetDiscretisation &sheet,
                      const linear_algebra::Vector              &du,
                      const AffineConstraints<double>           &constraints,
                      const std::vector<fe::QuadraturePointHistory> &history,
                      std::vector<fe::QuadraturePointHistory> &trial_history,
                      std::vector<fe::EnhancedParameters>     &trial_enhanced,
                      linear_algebra::SystemMatrix            *matrix,
                      linear_algebra::Vector                  &rhs,
                      linear_algebra::Vector                  &internal_force)
    {
      const AffineConstraints<double> &hanging
        = sheet.hanging_node_constraints();
      const std::vector<fe::CellGeometry> &cell_geometry
        = sheet.cell_geometry();
      std::atomic<int>          worst_status{0};
      std::atomic<unsigned int> plastic_points{0};
      std::atomic<unsigned int> pending_elements{0};
      // Under mpirun each rank evaluates its own cells (D215); the sums
      // over the ranks follow the loop (D199).

      auto worker
        = [&](const typename DoFHandler<3>::active_cell_iterator &cell,
              AssemblyScratch                                    &scratch,
              AssemblyCopy                                       &copy)
      {
        copy.active = false;
        if (!parallel::is_owned(*cell))
          return;
        const unsigned int index = cell->active_cell_index();
        cell->get_dof_indices(copy.dofs);
        copy.cell_index = index;
        double cell_du[fe::dofs_per_cell];
        for (unsigned int i = 0; i < fe::dofs_per_cell; ++i)
          cell_du[i] = du[copy.dofs[i]];
        // The state and geometry of a rank's own cells, in their order
        // (D217, D218).
        const unsigned int slot        = sheet.owned_cells().slot(index);
        const unsigned int first_point = slot * cell_geometry[slot].n_points();
        unsigned int       cell_plastic_points = 0;
        const fe::ElementStatus status
          = element.evaluate(cell_geometry[slot],
                             cell_du,
                             &history[first_point],
                             &trial_history[first_point],
                             trial_enhanced.empty()
                               ? scratch.no_enhanced_parameters
                               : trial_enhanced[slot],
                             copy.residual.begin(),
                             matrix != nullptr ? &copy.matrix : nullptr,
                             cell_plastic_points);
        if (status == fe::ElementStatus::enhanced_pending)
          ++pending_elements;
        else if (status != fe::ElementStatus::ok)
        {
          // Atomic maximum: the most specific failure is reported.
          const int code = static_cast<int>(status);
          int       seen = worst_status.load();
          while (seen < code && !worst_status.compare_exchange_weak(seen, code))
          {
          }
          return;
        }
        plastic_points += cell_plastic_points;
        copy.active = true;
      };

      // Serial, in the cells' order: the sums do not depend on the threads.
      auto copier = [&](const AssemblyCopy &copy)
      {
        if (!copy.active)
          return;
        for (unsigned int i = 0; i < fe::dofs_per_cell; ++i)
          internal_force[copy.dofs[i]] += copy.residual(i);
        if (matrix != nullptr
            && std::none_of(copy.dofs.begin(),
                            copy.dofs.end(),
                            [&](const types::global_dof_index dof)
                            { return constraints.is_constrained(dof); }))
        {
          // What distribute_local_to_global adds for a cell without
          // constrained dofs, without its bookkeeping (D98, D99).
          matrix->add_cell_matrix(copy.cell_index, copy.matrix);
          for (unsigned int i = 0; i < fe::dofs_per_cell; ++i)
            if (copy.residual(i) != 0.)
              rhs(copy.dofs[i]) -= copy.residual(i);
          return;
        }
        linear_algebra::Vector cell_rhs(copy.residual);
        cell_rhs *= -1.;
        if (matrix != nullptr)
          matrix->add_local(constraints, copy.matrix, cell_rhs, copy.dofs, rhs);
        else
          constraints.distribute_local_to_global(cell_rhs, copy.dofs, rhs);
      };

      const DoFHandler<3> &dof_handler = sheet.dof_handler();
      WorkStream::run(dof_handler.begin_active(),
                      dof_handler.end(),
                      worker,
                      copier,
                      AssemblyScratch(),
                      AssemblyCopy());
      int                status  = worst_status.load();
      unsigned long long plastic = plastic_points.load(),
                         pending = pending_elements.load();
      if (parallel::n_ranks() > 1)
      {
        parallel::sum(rhs.begin(), rhs.size());
        parallel::sum(internal_force.begin(), internal_force.size());
        if (matrix != nullptr)
          matrix->sum_over_ranks();
        status  = parallel::maximum(status);
        plastic = parallel::sum(plastic);
        pending = parallel::sum(pending);
      }
      // The nodal forces of hanging vertices belong to their masters: the
      // reactions of a face are those of the condensed system.
      if (hanging.n_constraints() > 0)
        hanging.condense(internal_force);
      return {static_cast<fe::ElementStatus>(status),
              static_cast<unsigned int>(plastic),
              static_cast<unsigned int>(pending)};
    }
  } // namespace problem
} // namespace deepdraw
