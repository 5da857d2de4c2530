// Adaptive refinement during the run (subsection Adaptivity, doc/theory.md
// §8, D80-D85): between converged increments the indicator flags cells,
// the mesh is refined and the committed state carried over (state_transfer.h,
// contact::ContactCoupling::transfer), the system is rebuilt with the
// hanging-node constraints, and one Newton solve at the same load restores
// equilibrium before the next increment.
#include <deal.II/base/timer.h>
#include <deepdraw/adaptivity/refinement_indicator.h>
#include <deepdraw/adaptivity/state_transfer.h>
#include <deepdraw/blank/nodal_surface_area.h>
#include <deepdraw/fe/vertex_parents.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/problem/forming_problem.h>
#include <map>

namespace deepdraw
{
  namespace problem
  {
    bool
    FormingProblem::adapt_mesh(const bool last_increment, std::string &reason)
    {
      const adaptivity::AdaptivityParameters &parameters
        = adaptivity_parameters;
      if (!parameters.enabled || last_increment
          || state.increment_number % parameters.interval != 0)
        return true;
      Timer                     timer;
      const std::vector<double> indicator = scaled_refinement_indicator();
      if (adaptivity::flag_cells_for_refinement(triangulation,
                                                indicator,
                                                1.,
                                                parameters)
          == 0)
        return true;

      // The flagged cells, for a resume (D84).
      std::vector<std::array<int, 3>> flagged;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->refine_flag_set())
          flagged.push_back(
            {{cell->level(), cell->index(), int(cell->refine_flag_set())}});
      state.refinements.push_back(flagged);

      RefinementRecord record{};
      record.cycle        = state.refinements.size();
      record.increment    = state.increment_number;
      record.load         = state.load;
      record.cells_before = triangulation.n_active_cells();
      refine_and_rebuild();
      record.cells_after      = triangulation.n_active_cells();
      record.hanging_vertices = hanging_node_constraints.n_constraints() / 3;

      const IncrementOutcome outcome = reequilibrate(record.iterations);
      reason                         = solver::describe(outcome);
      if (outcome != IncrementOutcome::converged)
        return false;
      const std::vector<double> &contact_residuals = contact_residual_history;
      record.initial_force_residual
        = residual_history.empty() ? 0. : residual_history.front();
      record.initial_contact_residual
        = contact_residuals.empty() ? 0. : contact_residuals.front();
      record.force_residual
        = residual_history.empty() ? 0. : residual_history.back();
      record.wall_time = timer.wall_time();
      refinement_history.push_back(record);
      // The re-equilibration's orderings belong to no increment's row of
      // statistics.csv (a run resumed after it must count the same).
      reported_solver_statistics = linear_solver->statistics();
      adaptivity_file.add_row(
        {double(record.cycle),
         double(record.increment),
         record.load,
         double(record.cells_before),
         double(record.cells_after),
         double(record.hanging_vertices),
         double(dof_handler.n_dofs()),
         double(newton_unknowns.size() - dof_handler.n_dofs()),
         record.initial_force_residual,
         record.initial_contact_residual,
         double(record.iterations),
         record.force_residual,
         record.wall_time});
      return true;
    }


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


    std::vector<double>
    FormingProblem::scaled_refinement_indicator() const
    {
      const adaptivity::AdaptivityParameters &parameters
        = adaptivity_parameters;
      if (parameters.indicator == "region")
        return scaled(adaptivity::region_indicator(triangulation,
                                                   initial_vertices,
                                                   parameters.region_min,
                                                   parameters.region_max),
                      0.5);
      std::vector<double> result;
      if (parameters.indicator != "tool curvature")
      {
        result = adaptivity::plastic_strain_jump(triangulation, state.history);
        // In-plane refinement with the smooth placement refines whole
        // columns (D89); the tool-curvature indicator does so itself.
        if (parameters.refinement == "in_plane"
            && parameters.vertex_placement == "smooth")
          result = adaptivity::column_maximum(triangulation, result);
        result = scaled(result, parameters.jump_threshold);
      }
      if (parameters.indicator != "plastic strain jump")
      {
        // h kappa of the tools (D94).
        std::vector<unsigned int> sheet_faces;
        for (const contact::ToolDefinition &tool : contact.tool_definitions())
          sheet_faces.push_back(tool.sheet_face);
        const std::vector<double> curvature
          = scaled(adaptivity::tool_curvature_indicator(triangulation,
                                                        contact.tools(),
                                                        sheet_faces,
                                                        geometry.thickness),
                   parameters.curvature_threshold);
        if (result.empty())
          return curvature;
        for (std::size_t k = 0; k < result.size(); ++k)
          result[k] = std::max(result[k], curvature[k]);
      }
      return result;
    }


    void
    FormingProblem::refine_and_rebuild()
    {
      const unsigned int n_old_vertices = triangulation.n_vertices();
      contact::ContactCoupling::Snapshot contact_snapshot;
      std::vector<double>                old_area;
      if (contact.active())
      {
        contact_snapshot = contact.snapshot(state.converged_solution,
                                            state.previous_converged_solution);
        old_area         = blank::nodal_surface_area(triangulation);
      }
      adaptivity::TransferOptions options;
      options.vertex_placement
        = adaptivity_parameters.vertex_placement == "smooth"
            ? adaptivity::VertexPlacement::smooth
            : adaptivity::VertexPlacement::linear;
      options.history = adaptivity_parameters.history_transfer == "interpolated"
                          ? adaptivity::HistoryTransfer::interpolated
                          : adaptivity::HistoryTransfer::nearest;
      options.material = material.get();
      adaptivity::refine_and_transfer(triangulation,
                                      dof_handler,
                                      state,
                                      options);
      const std::vector<fe::VertexParents> parents
        = fe::vertex_parents(triangulation, n_old_vertices);
      add_blank_parents(parents, n_old_vertices);
      setup_dofs();

      // The transfer kept the displacement blocks of the Newton solutions;
      // the contact blocks are those of the new pairs, started from the
      // pairs at the parents of their nodes (D83).
      const types::global_dof_index   n_u = dof_handler.n_dofs();
      std::array<Vector<double> *, 2> solutions
        = {{&state.converged_solution, &state.previous_converged_solution}};
      std::array<Vector<double>, 2> extended;
      for (unsigned int s = 0; s < 2; ++s)
      {
        extended[s].reinit(newton_unknowns.size());
        for (types::global_dof_index i = 0; i < n_u; ++i)
          extended[s][i] = (*solutions[s])[i];
      }
      if (contact.active())
      {
        contact.transfer(contact_snapshot,
                         parents,
                         old_area,
                         blank::nodal_surface_area(triangulation),
                         extended[0],
                         extended[1]);
        state.contact = contact.committed_history();
      }
      state.converged_solution          = std::move(extended[0]);
      state.previous_converged_solution = std::move(extended[1]);
      trial_history                     = state.history;
      trial_enhanced_parameters         = state.enhanced_parameters;
      newton_unknowns                   = state.converged_solution;
      update_cell_geometry();
      compute_thickness();
    }


    void
    FormingProblem::add_blank_parents(
      const std::vector<fe::VertexParents> &parents,
      const unsigned int                    n_old_vertices)
    {
      if (blank_vertex_parents.empty())
        for (unsigned int v = 0; v < n_old_vertices; ++v)
          blank_vertex_parents.push_back({{v, 1.}});
      blank_vertex_parents.resize(triangulation.n_vertices());
      initial_vertices.resize(triangulation.n_vertices());
      // The initial position of a new vertex is the Q1 interpolation of the
      // blank's, as its displacement is (doc/theory.md §8): prescribed
      // displacements and the region indicator need it. Interpolated from
      // the blank's vertices, not as x - u, so that a resume (which replays
      // the refinements) finds the same positions bit for bit.
      for (unsigned int v = n_old_vertices; v < triangulation.n_vertices(); ++v)
      {
        std::map<unsigned int, double> sum;
        for (const auto &[parent, weight] : parents[v])
          for (const auto &[blank, w] : blank_vertex_parents[parent])
            sum[blank] += weight * w;
        blank_vertex_parents[v].assign(sum.begin(), sum.end());
        Point<3> X;
        for (const auto &[blank, w] : blank_vertex_parents[v])
          X += w * initial_vertices[blank];
        initial_vertices[v] = X;
      }
    }


    void
    FormingProblem::replay_refinements(
      const std::vector<std::vector<std::array<int, 3>>> &cycles)
    {
      for (const auto &cycle : cycles)
      {
        const unsigned int n_old_vertices = triangulation.n_vertices();
        for (const auto &[level, index, refinement] : cycle)
        {
          if (level < 0 || level >= int(triangulation.n_levels()) || index < 0
              || index >= int(triangulation.n_cells(level)))
            throw InputError("--resume: the checkpoint's refinements do not "
                             "belong to this mesh");
          const Triangulation<3>::cell_iterator cell(&triangulation,
                                                     level,
                                                     index);
          if (!cell->is_active())
            throw InputError("--resume: the checkpoint's refinements do not "
                             "belong to this mesh");
          cell->set_refine_flag(RefinementCase<3>(refinement));
        }
        triangulation.execute_coarsening_and_refinement();
        add_blank_parents(fe::vertex_parents(triangulation, n_old_vertices),
                          n_old_vertices);
      }
      dof_handler.distribute_dofs(fe);
      setup_dofs();
    }


    FormingProblem::IncrementOutcome
    FormingProblem::reequilibrate(unsigned int &iterations)
    {
      // The transferred stress is not in equilibrium on the refined mesh
      // (nearest-point transfer, D57): Newton at the same load, from du = 0
      // and the transferred multipliers (doc/theory.md §8.3).
      const types::global_dof_index n_u = dof_handler.n_dofs();
      prepare_increment(state.load, state.load);
      linear_solver->reset_reduction();
      newton_unknowns = state.converged_solution;
      for (types::global_dof_index i = 0; i < n_u; ++i)
        newton_unknowns[i] = 0.;
      start_enhanced_parameters(0.);
      residual_history.clear();
      contact_residual_history.clear();
      contact_changes          = 0;
      changes_reported         = 0;
      iterations               = 0;
      reequilibrating          = true;
      IncrementOutcome outcome = assemble_at(newton_unknowns, false);
      if (outcome == IncrementOutcome::converged)
      {
        // No stagnation cut (D89): it saves the time of an increment that
        // a cut-back would redo smaller, but a re-equilibration has no
        // smaller step; it may use all of Maximum iterations.
        solver::NewtonParameters settings = newton_parameters;
        settings.stagnation_iterations    = 0;
        solver::NewtonIncrement newton(settings);
        outcome          = newton.run(*this, newton_unknowns, true, iterations);
        residual_history = newton.force_residuals();
        contact_residual_history = newton.contact_residuals();
      }
      reequilibrating = false;
      if (outcome != IncrementOutcome::converged)
        return outcome;

      // Committed: history, contact state and configuration; the Newton
      // solution keeps the last increment's du (the extrapolation predictor
      // scales it) with the re-equilibrated multipliers and tool positions.
      state.history = trial_history;
      for (types::global_dof_index i = n_u; i < newton_unknowns.size(); ++i)
        state.converged_solution[i] = newton_unknowns[i];
      if (contact.active())
      {
        contact.commit(newton_unknowns);
        state.contact = contact.committed_history();
      }
      move_mesh();
      return outcome;
    }
  } // namespace problem
} // namespace deepdraw
