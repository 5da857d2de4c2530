// Adaptive refinement of FormingProblem between converged increments
// (subsection Adaptivity, doc/theory.md §8, D80-D85): the mesh and the
// committed state by adaptivity::MeshAdaptation, then the Newton system of
// the refined mesh, the contact pairs carried over (D83), and one Newton
// solve at the same load that restores equilibrium.
#include <deepdraw/blank/nodal_surface_area.h>
#include <deepdraw/problem/forming_problem.h>

namespace deepdraw
{
  namespace problem
  {
    bool
    FormingProblem::adapt_mesh(const bool last_increment, std::string &reason)
    {
      if (!adaptation->flag_cells(discretisation,
                                  committed,
                                  contact_coupling,
                                  parameters.geometry.thickness,
                                  last_increment))
        return true;

      contact::ContactCoupling::Snapshot snapshot;
      std::vector<double>                old_area;
      if (contact_coupling.active())
      {
        snapshot
          = contact_coupling.snapshot(committed.converged_solution,
                                      committed.previous_converged_solution);
        old_area = blank::nodal_surface_area(discretisation.triangulation());
      }
      const std::vector<fe::VertexParents> parents
        = adaptation->refine(discretisation, committed, *material_model);
      set_up_system();

      // The transfer kept the displacement blocks of the Newton solutions;
      // the contact blocks are those of the new pairs, started from the
      // pairs at the parents of their nodes (D83).
      const types::global_dof_index n_u = discretisation.n_displacement_dofs();
      std::array<Vector<double> *, 2> solutions
        = {{&committed.converged_solution,
            &committed.previous_converged_solution}};
      std::array<Vector<double>, 2> extended;
      for (unsigned int s = 0; s < 2; ++s)
      {
        extended[s].reinit(newton_unknowns.size());
        for (types::global_dof_index i = 0; i < n_u; ++i)
          extended[s][i] = (*solutions[s])[i];
      }
      if (contact_coupling.active())
      {
        contact_coupling.transfer(snapshot,
                                  parents,
                                  old_area,
                                  blank::nodal_surface_area(
                                    discretisation.triangulation()),
                                  extended[0],
                                  extended[1]);
        committed.contact = contact_coupling.committed_history();
      }
      committed.converged_solution          = std::move(extended[0]);
      committed.previous_converged_solution = std::move(extended[1]);
      trial_history                         = committed.history;
      trial_enhanced_parameters             = committed.enhanced_parameters;
      newton_unknowns                       = committed.converged_solution;

      unsigned int           iterations = 0;
      const IncrementOutcome outcome    = reequilibrate(iterations);
      reason                            = solver::describe(outcome);
      if (outcome != IncrementOutcome::converged)
        return false;
      adaptation->record(discretisation,
                         newton_unknowns.size(),
                         progress.force_residuals,
                         progress.contact_residuals,
                         iterations);
      // The re-equilibration's orderings belong to no increment's row of
      // statistics.csv (a run resumed after it must count the same).
      reported_solver_statistics = linear_system->statistics();
      return true;
    }


    FormingProblem::IncrementOutcome
    FormingProblem::reequilibrate(unsigned int &iterations)
    {
      // The transferred stress is not in equilibrium on the refined mesh
      // (nearest-point transfer, D57): Newton at the same load, from du = 0
      // and the transferred multipliers (doc/theory.md §8.3).
      const types::global_dof_index n_u = discretisation.n_displacement_dofs();
      prepare_increment(committed.load, committed.load);
      linear_system->reset_reduction();
      newton_unknowns = committed.converged_solution;
      for (types::global_dof_index i = 0; i < n_u; ++i)
        newton_unknowns[i] = 0.;
      start_enhanced_parameters(0.);
      progress.start_attempt();
      iterations               = 0;
      progress.reequilibrating = true;
      IncrementOutcome outcome = assemble_at(newton_unknowns, false);
      if (outcome == IncrementOutcome::converged)
      {
        // No stagnation cut (D89): it saves the time of an increment that
        // a cut-back would redo smaller, but a re-equilibration has no
        // smaller step; it may use all of Maximum iterations.
        solver::NewtonParameters settings = parameters.newton;
        settings.stagnation_iterations    = 0;
        solver::NewtonIncrement newton(settings);
        outcome = newton.run(*this, newton_unknowns, true, iterations);
        progress.keep_residuals(newton);
      }
      progress.reequilibrating = false;
      if (outcome != IncrementOutcome::converged)
        return outcome;

      // Committed: history, contact state and configuration; the Newton
      // solution keeps the last increment's du (the extrapolation predictor
      // scales it) with the re-equilibrated multipliers and tool positions.
      committed.history = trial_history;
      for (types::global_dof_index i = n_u; i < newton_unknowns.size(); ++i)
        committed.converged_solution[i] = newton_unknowns[i];
      if (contact_coupling.active())
      {
        contact_coupling.commit(newton_unknowns);
        committed.contact = contact_coupling.committed_history();
      }
      move_mesh();
      return outcome;
    }
  } // namespace problem
} // namespace deepdraw
