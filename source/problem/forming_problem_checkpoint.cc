// Checkpoint and restart of FormingProblem (doc/user_guide.md §6, D55,
// D101): the committed state with its stage, the parameters, the output
// tables' sizes and the post-processors' data; a resumed run continues the
// same arithmetic from there.
#include <deepdraw/problem/forming_problem.h>

namespace deepdraw
{
  namespace problem
  {
    void
    FormingProblem::save_checkpoint() const
    {
      state::Checkpoint checkpoint;
      checkpoint.parameters     = parameters.listing;
      checkpoint.state          = model->state();
      checkpoint.table_sizes    = table_sizes;
      checkpoint.postprocessors = postprocessors.save();
      state::write_checkpoint(state::checkpoint_file(
                                parameters.output.output_directory),
                              checkpoint);
    }


    void
    FormingProblem::restore_checkpoint()
    {
      const std::string &directory  = parameters.output.output_directory;
      const std::string  filename   = state::checkpoint_file(directory);
      state::Checkpoint  checkpoint = state::read_checkpoint(filename);
      state::check_resumable(checkpoint,
                             filename,
                             parameters.listing,
                             parameters.default_listing,
                             parameters.stages.size());
      model->restore(std::move(checkpoint.state));
      newton_unknowns = model->state().converged_solution;
      postprocessors.initialize(*view);
      state::truncate_tables(directory, checkpoint.table_sizes);
      postprocessors.load(checkpoint.postprocessors);
    }
  } // namespace problem
} // namespace deepdraw
