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
      // A release stage keeps its mesh: its loads and supports belong to
      // the nodes it began with (D150).
      if (model->stage().kind == process::Stage::Kind::release)
        return true;
      if (!adaptation->flag_cells(model->sheet(),
                                  model->state(),
                                  model->contact(),
                                  parameters.geometry.thickness,
                                  last_increment))
        return true;
      model->refine(*adaptation);
      increments->reset_unknowns();
      postprocessors.initialize(*view);

      unsigned int           iterations = 0;
      const IncrementOutcome outcome    = increments->reequilibrate(iterations);
      reason                            = solver::describe(outcome);
      if (outcome != IncrementOutcome::converged)
        return false;
      adaptation->record(model->sheet(),
                         model->n_unknowns(),
                         increments->progress().force_residuals,
                         increments->progress().contact_residuals,
                         iterations);
      // The re-equilibration's orderings belong to no increment's row of
      // statistics.csv (a run resumed after it must count the same).
      run_record.reported_solver_statistics
        = model->linear_system().statistics();
      return true;
    }
  } // namespace problem
} // namespace deepdraw
