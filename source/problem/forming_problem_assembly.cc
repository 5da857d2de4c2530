// Global assembly of the sheet's elements (fe::HexahedronElement, the
// residual and exact tangent of each element technology, doc/theory.md §3)
// and of the contact terms; the cell geometry wrt x_t is computed once per
// increment (doc/decisions.md D13).
#include <algorithm>
#include <array>
#include <atomic>
#include <deal.II/base/timer.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_values.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/problem/forming_problem.h>
#include <limits>

namespace deepdraw
{
  namespace problem
  {
    void
    FormingProblem::update_cell_geometry()
    {
      FEValues<3> fe_values(fe_scalar,
                            fe::selective_reduced_quadrature(),
                            fe::cell_geometry_flags());
      cell_geometry.resize(triangulation.n_active_cells());
      for (const auto &cell : triangulation.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe::compute_cell_geometry(fe_values,
                                  cell_geometry[cell->active_cell_index()]);
      }
    }


    void
    FormingProblem::find_cell_matrix_positions()
    {
      constexpr unsigned int n = fe::dofs_per_cell;
      AssertThrow(sparsity_pattern.n_nonzero_elements()
                    < std::numeric_limits<unsigned int>::max(),
                  ExcMessage("more matrix entries than unsigned int holds"));
      // matrix_values (assemble) starts at the entry (0, 0): a square
      // compressed pattern stores each row's diagonal first.
      AssertThrow(sparsity_pattern.n_rows() == 0 || sparsity_pattern(0, 0) == 0,
                  ExcInternalError());
      cell_matrix_positions.resize(std::size_t(triangulation.n_active_cells())
                                   * n * n);
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


    namespace
    {
      struct AssemblyScratch
      {
        // Stands in for the enhanced parameters of elements without any.
        fe::EnhancedParameters no_enhanced_parameters;
      };

      // What AffineConstraints::distribute_local_to_global adds for a cell
      // none of whose dofs is constrained, through the entries' positions
      // in the matrix's values (find_cell_matrix_positions): each entry
      // gets the same one addition per cell, in the serial copier's cell
      // order, so the sums are the same to the last bit (D98, D99).
      // rhs = -residual.
      void
      add_unconstrained_cell(const FullMatrix<double> &matrix,
                             const Vector<double>     &residual,
                             const std::vector<types::global_dof_index> &dofs,
                             const unsigned int *positions,
                             double             *matrix_values,
                             Vector<double>     &system_rhs)
      {
        constexpr unsigned int n     = fe::dofs_per_cell;
        const double          *local = &matrix(0, 0);
        for (unsigned int k = 0; k < n * n; ++k)
          matrix_values[positions[k]] += local[k];
        for (unsigned int i = 0; i < n; ++i)
          if (residual(i) != 0.)
            system_rhs(dofs[i]) -= residual(i);
      }


      struct AssemblyCopy
      {
        FullMatrix<double> matrix   = FullMatrix<double>(24, 24);
        Vector<double>     residual = Vector<double>(24);
        std::vector<types::global_dof_index> dofs
          = std::vector<types::global_dof_index>(24);
        unsigned int cell_index = 0;
        bool         active     = false;
      };
    } // namespace


    FormingProblem::IncrementOutcome
    FormingProblem::assemble(const Vector<double>            &unknowns,
                             const AffineConstraints<double> &constraints,
                             const bool                       assemble_matrix)
    {
      Timer timer;
      // On a refined mesh the hanging dofs are evaluated from their masters
      // (an iterate may not satisfy the constraints, e.g. after the
      // predictor's damped step).
      Vector<double> consistent;
      if (hanging_node_constraints.n_constraints() > 0)
      {
        consistent = unknowns;
        hanging_node_constraints.distribute(consistent);
      }
      const Vector<double> &du
        = hanging_node_constraints.n_constraints() > 0 ? consistent : unknowns;
      if (assemble_matrix)
        system_matrix = 0.;
      system_rhs     = 0.;
      internal_force = 0.;
      // The values array of system_matrix (as MumpsFactorization reads
      // it): entry k of the pattern is matrix_values[k].
      double          *matrix_values = system_matrix.n_nonzero_elements() > 0
                                         ? const_cast<double *>(&system_matrix(0, 0))
                                         : nullptr;
      std::atomic<int> worst_status{0};
      std::atomic<unsigned int> plastic_points{0};

      auto worker
        = [&](const typename DoFHandler<3>::active_cell_iterator &cell,
              AssemblyScratch                                    &scratch,
              AssemblyCopy                                       &copy)
      {
        copy.active = false;
        cell->get_dof_indices(copy.dofs);
        const unsigned int index = cell->active_cell_index();
        copy.cell_index          = index;
        double cell_du[fe::dofs_per_cell];
        for (unsigned int i = 0; i < fe::dofs_per_cell; ++i)
          cell_du[i] = du[copy.dofs[i]];
        const unsigned int      first_point = index * fe::n_weighted_points;
        unsigned int            cell_plastic_points = 0;
        const fe::ElementStatus status
          = element->evaluate(cell_geometry[index],
                              cell_du,
                              &state.history[first_point],
                              &trial_history[first_point],
                              trial_enhanced_parameters.empty()
                                ? scratch.no_enhanced_parameters
                                : trial_enhanced_parameters[index],
                              copy.residual.begin(),
                              assemble_matrix ? &copy.matrix : nullptr,
                              cell_plastic_points);
        if (status != fe::ElementStatus::ok)
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

      auto copier = [&](const AssemblyCopy &copy)
      {
        if (!copy.active)
          return;
        for (unsigned int i = 0; i < 24; ++i)
          internal_force[copy.dofs[i]] += copy.residual(i);
        if (assemble_matrix
            && std::none_of(copy.dofs.begin(),
                            copy.dofs.end(),
                            [&](const types::global_dof_index dof)
                            { return constraints.is_constrained(dof); }))
        {
          add_unconstrained_cell(
            copy.matrix,
            copy.residual,
            copy.dofs,
            &cell_matrix_positions[std::size_t(copy.cell_index)
                                   * fe::dofs_per_cell * fe::dofs_per_cell],
            matrix_values,
            system_rhs);
          return;
        }
        Vector<double> rhs(copy.residual);
        rhs *= -1.;
        if (assemble_matrix)
          constraints.distribute_local_to_global(copy.matrix,
                                                 rhs,
                                                 copy.dofs,
                                                 system_matrix,
                                                 system_rhs);
        else
          constraints.distribute_local_to_global(rhs, copy.dofs, system_rhs);
      };

      WorkStream::run(dof_handler.begin_active(),
                      dof_handler.end(),
                      worker,
                      copier,
                      AssemblyScratch(),
                      AssemblyCopy());
      n_plastic_points = plastic_points;
      // The nodal forces of hanging vertices belong to their masters: the
      // reactions of a face are those of the condensed system.
      if (hanging_node_constraints.n_constraints() > 0)
        hanging_node_constraints.condense(internal_force);
      assembly_time += timer.wall_time();

      // Contact forces and their constraints, after the elements so that
      // the assembly time excludes the contact search.
      last_assembly_changes = 0;
      if (contact.active())
        last_assembly_changes
          = contact.assemble(triangulation.get_vertices(),
                             du,
                             constraints,
                             assemble_matrix ? &system_matrix : nullptr,
                             system_rhs,
                             target_load,
                             &constraints == &predictor_constraints);
      contact_changes += last_assembly_changes;

      switch (static_cast<fe::ElementStatus>(worst_status.load()))
      {
        case fe::ElementStatus::ok:
          return IncrementOutcome::converged;
        case fe::ElementStatus::inverted:
          return IncrementOutcome::inverted_element;
        case fe::ElementStatus::return_mapping_failed:
          return IncrementOutcome::return_mapping_failed;
        case fe::ElementStatus::enhanced_not_converged:
          return IncrementOutcome::enhanced_not_converged;
      }
      return IncrementOutcome::return_mapping_failed;
    }


    bool
    FormingProblem::assemble_system(const Vector<double> &du)
    {
      AffineConstraints<double> none;
      none.close();
      return assemble(du, none, true) == IncrementOutcome::converged;
    }


    bool
    FormingProblem::evaluate_residual(const Vector<double> &du,
                                      Vector<double>       &residual,
                                      FullMatrix<double>   *tangent)
    {
      AffineConstraints<double> none;
      none.close();
      const IncrementOutcome status = assemble(du, none, tangent != nullptr);
      // Without constraints rhs = -r for all equations, contact included.
      residual = system_rhs;
      residual *= -1.;
      if (tangent != nullptr)
      {
        tangent->reinit(system_matrix.m(), system_matrix.n());
        for (unsigned int i = 0; i < system_matrix.m(); ++i)
          for (auto entry = system_matrix.begin(i);
               entry != system_matrix.end(i);
               ++entry)
            (*tangent)(i, entry->column()) = entry->value();
      }
      return status == IncrementOutcome::converged;
    }
  } // namespace problem
} // namespace deepdraw
