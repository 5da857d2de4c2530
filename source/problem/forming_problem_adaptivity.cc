// Adaptive refinement between converged increments (subsection Adaptivity,
// doc/theory.md §8, D80-D85): the cells flagged and refined with the
// committed state by adaptivity::MeshAdaptation and SheetModel, then one
// Newton solve at the same load that restores equilibrium.
#include <deepdraw/problem/forming_problem.h>

namespace deepdraw
{
  namespace problem
  {
    bool
    FormingProblem::adapt_mesh(const bool last_increment, std::string &reason)
    {
      if (!adaptation->flag_cells(model->sheet(),
                                  model->state(),
                                  model->contact(),
                                  parameters.geometry.thickness,
                                  last_increment))
        return true;
      model->refine(*adaptation);
      newton_unknowns = model->state().converged_solution;
      postprocessors.initialize(*view);

      unsigned int           iterations = 0;
      const IncrementOutcome outcome    = reequilibrate(iterations);
      reason                            = solver::describe(outcome);
      if (outcome != IncrementOutcome::converged)
        return false;
      adaptation->record(model->sheet(),
                         model->n_unknowns(),
                         progress.force_residuals,
                         progress.contact_residuals,
                         iterations);
      // The re-equilibration's orderings belong to no increment's row of
      // statistics.csv (a run resumed after it must count the same).
      reported_solver_statistics = model->linear_system().statistics();
      return true;
    }


    FormingProblem::IncrementOutcome
    FormingProblem::reequilibrate(unsigned int &iterations)
    {
      // The transferred stress is not in equilibrium on the refined mesh
      // (nearest-point transfer, D57): Newton at the same load, from du = 0
      // and the transferred multipliers (doc/theory.md §8.3).
      const double load = model->state().load;
      prepare_increment(load, load);
      model->linear_system().reset_reduction();
      start_from_converged_state();
      model->start_enhanced_parameters(0.);
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
      if (outcome == IncrementOutcome::converged)
        model->commit_equilibrium(newton_unknowns);
      return outcome;
    }
  } // namespace problem
} // namespace deepdraw
