// FormingProblem: its construction, what tests and benchmarks call
// directly, and its checkpoints. The run is in forming_problem_run.cc, one
// increment in increment_solver.cc.
#include <deepdraw/problem/forming_problem.h>

namespace deepdraw
{
  namespace problem
  {
    void
    FormingProblem::declare_parameters(ParameterHandler &prm)
    {
      ModelParameters::declare_parameters(prm);
    }


    FormingProblem::FormingProblem(ParameterHandler  &prm,
                                   const std::string &input_directory)
    {
      parameters.parse_parameters(prm, input_directory);
      postprocessors.parse_parameters(prm, input_directory);
      model = std::make_unique<SheetModel>(prm, parameters, input_directory);
      adaptation
        = std::make_unique<adaptivity::MeshAdaptation>(parameters.adaptivity);
      view
        = std::make_unique<SimulationView>(*model, run_record, postprocessors);
      increments = std::make_unique<IncrementSolver>(*model, parameters.newton);
      postprocessors.initialize(*view);
    }


    const postprocess::SimulationAccess &
    FormingProblem::access() const
    {
      return *view;
    }


    IncrementSolver &
    FormingProblem::increment_solver()
    {
      return *increments;
    }


    const std::vector<adaptivity::RefinementRecord> &
    FormingProblem::refinement_records() const
    {
      return adaptation->records();
    }


    // Checkpoint and restart (doc/user_guide.md §6, D55, D101): the
    // committed state with its stage, the parameters, the output tables'
    // sizes and the post-processors' data.
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
      increments->reset_unknowns();
      postprocessors.initialize(*view);
      state::truncate_tables(directory, checkpoint.table_sizes);
      postprocessors.load(checkpoint.postprocessors);
    }
  } // namespace problem
} // namespace deepdraw
