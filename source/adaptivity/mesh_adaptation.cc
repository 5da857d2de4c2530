#include <deepdraw/adaptivity/mesh_adaptation.h>
#include <deepdraw/adaptivity/refinement_indicator.h>
#include <deepdraw/adaptivity/state_transfer.h>

namespace deepdraw
{
  namespace adaptivity
  {
    namespace
    {
      // value / threshold where value exceeds threshold, else 0: above 1
      // exactly where the indicator selects, in the same order (a zero
      // threshold selects every positive value, ranked as 1 + value).
      std::vector<double>
      scaled(const std::vector<double> &values, const double threshold)
      {
        std::vector<double> result(values.size(), 0.);
        for (std::size_t k = 0; k < values.size(); ++k)
          if (values[k] > threshold)
            result[k] = threshold > 0. ? values[k] / threshold : 1. + values[k];
        return result;
      }
    } // namespace


    MeshAdaptation::MeshAdaptation(const AdaptivityParameters &parameters)
        : parameters(parameters)
    {
    }


    void
    MeshAdaptation::open(const std::string &directory, const bool resume)
    {
      if (!parameters.enabled)
        return;
      file.open(directory + "/adaptivity.csv",
                {"cycle",
                 "increment",
                 "load",
                 "cells_before",
                 "cells_after",
                 "hanging_vertices",
                 "displacement_unknowns",
                 "contact_unknowns",
                 "initial_force_residual",
                 "initial_contact_residual",
                 "reequilibration_iterations",
                 "force_residual",
                 "wall_s"},
                resume);
    }


    bool
    MeshAdaptation::flag_cells(discretisation::SheetDiscretisation &sheet,
                               state::SimulationState              &state,
                               const contact::ContactCoupling      &contact,
                               const double sheet_thickness,
                               const bool   last_increment)
    {
      if (!parameters.enabled || last_increment
          || state.increment_number % parameters.interval != 0)
        return false;
      timer.restart();
      Triangulation<3>         &mesh = sheet.triangulation();
      const std::vector<double> indicator
        = scaled_indicator(sheet, state, contact, sheet_thickness);
      if (flag_cells_for_refinement(mesh, indicator, 1., parameters) == 0)
        return false;

      // The flagged cells, for a resume (D84).
      std::vector<std::array<int, 3>> flagged;
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->refine_flag_set())
          flagged.push_back(
            {{cell->level(), cell->index(), int(cell->refine_flag_set())}});
      state.refinements.push_back(flagged);
      pending              = RefinementRecord{};
      pending.cycle        = state.refinements.size();
      pending.increment    = state.increment_number;
      pending.load         = state.load;
      pending.cells_before = mesh.n_active_cells();
      return true;
    }


    std::vector<fe::VertexParents>
    MeshAdaptation::refine(discretisation::SheetDiscretisation &sheet,
                           state::SimulationState              &state,
                           const material::ElastoPlasticity    &material,
                           const bool enhanced_parameters) const
    {
      const unsigned int n_old_vertices = sheet.triangulation().n_vertices();
      TransferOptions    options;
      options.vertex_placement = parameters.vertex_placement == "smooth"
                                   ? VertexPlacement::smooth
                                   : VertexPlacement::linear;
      options.history          = parameters.history_transfer == "interpolated"
                                   ? HistoryTransfer::interpolated
                                   : HistoryTransfer::nearest;
      options.material         = &material;
      // Each rank makes the records of its cells' children (D220) ...
      options.held_cells          = &sheet.owned_cells();
      options.points_per_cell     = sheet.n_points_per_cell();
      options.enhanced_parameters = enhanced_parameters;
      const std::vector<unsigned int> holders
        = refine_and_transfer(sheet.triangulation(),
                              sheet.dof_handler(),
                              state,
                              options);
      const std::vector<fe::VertexParents> parents
        = fe::vertex_parents(sheet.triangulation(), n_old_vertices);
      sheet.add_blank_parents(parents, n_old_vertices);
      sheet.distribute_dofs();
      // ... and sends them to the ranks that evaluate them on the new
      // partition.
      const parallel::OwnedCells &cells = sheet.owned_cells();
      state.history = cells.collect_from_holders(std::move(state.history),
                                                 sheet.n_points_per_cell(),
                                                 holders);
      state.enhanced_parameters
        = cells.collect_from_holders(std::move(state.enhanced_parameters),
                                     enhanced_parameters ? 1 : 0,
                                     holders);
      return parents;
    }


    void
    MeshAdaptation::record(const discretisation::SheetDiscretisation &sheet,
                           const types::global_dof_index n_unknowns,
                           const std::vector<double>    &force_residuals,
                           const std::vector<double>    &contact_residuals,
                           const unsigned int            iterations)
    {
      RefinementRecord &record = pending;
      record.cells_after       = sheet.triangulation().n_active_cells();
      record.hanging_vertices
        = sheet.hanging_node_constraints().n_constraints() / 3;
      record.iterations = iterations;
      record.initial_force_residual
        = force_residuals.empty() ? 0. : force_residuals.front();
      record.initial_contact_residual
        = contact_residuals.empty() ? 0. : contact_residuals.front();
      record.force_residual
        = force_residuals.empty() ? 0. : force_residuals.back();
      record.wall_time = timer.wall_time();
      history.push_back(record);
      const types::global_dof_index n_u = sheet.n_displacement_dofs();
      file.add_row({double(record.cycle),
                    double(record.increment),
                    record.load,
                    double(record.cells_before),
                    double(record.cells_after),
                    double(record.hanging_vertices),
                    double(n_u),
                    double(n_unknowns - n_u),
                    record.initial_force_residual,
                    record.initial_contact_residual,
                    double(record.iterations),
                    record.force_residual,
                    record.wall_time});
    }


    const std::vector<RefinementRecord> &
    MeshAdaptation::records() const
    {
      return history;
    }


    std::vector<double>
    MeshAdaptation::scaled_indicator(
      const discretisation::SheetDiscretisation &sheet,
      const state::SimulationState              &state,
      const contact::ContactCoupling            &contact,
      const double                               sheet_thickness) const
    {
      const Triangulation<3> &mesh = sheet.triangulation();
      if (parameters.indicator == "region")
        return scaled(region_indicator(mesh,
                                       sheet.initial_vertices(),
                                       parameters.region_min,
                                       parameters.region_max),
                      0.5);
      std::vector<double> result;
      if (parameters.indicator != "tool curvature")
      {
        result = plastic_strain_jump(mesh, sheet.owned_cells(), state.history);
        // In-plane refinement with the smooth placement refines whole
        // columns (D89); the tool-curvature indicator does so itself.
        if (parameters.refinement == "in_plane"
            && parameters.vertex_placement == "smooth")
          result = column_maximum(mesh, result);
        result = scaled(result, parameters.jump_threshold);
      }
      if (parameters.indicator != "plastic strain jump")
      {
        // h kappa of the tools that take part (D94).
        std::vector<geometry::RigidTool> tools;
        std::vector<unsigned int>        sheet_faces;
        for (unsigned int k = 0; k < contact.tools().size(); ++k)
          if (contact.takes_part(k))
          {
            tools.push_back(contact.tools()[k]);
            sheet_faces.push_back(contact.tool_definitions()[k].sheet_face);
          }
        const std::vector<double> curvature = scaled(
          tool_curvature_indicator(mesh, tools, sheet_faces, sheet_thickness),
          parameters.curvature_threshold);
        if (result.empty())
          return curvature;
        for (std::size_t k = 0; k < result.size(); ++k)
          result[k] = std::max(result[k], curvature[k]);
      }
      return result;
    }
  } // namespace adaptivity
} // namespace deepdraw
