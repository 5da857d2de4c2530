// FormingProblem: its construction, what tests and benchmarks call
// directly, and its checkpoints. The run is in forming_problem_run.cc, one
// increment in increment_solver.cc.
#include <deepdraw/io/input_error.h>
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
      input_files = state::digest_input_files(input_file_names());
    }


    std::vector<std::pair<std::string, std::string>>
    FormingProblem::input_file_names() const
    {
      std::vector<std::pair<std::string, std::string>> files;
      using Outline = blank::BlankGeometry::Outline;
      if (parameters.geometry.outline == Outline::polygon)
        files.emplace_back("Geometry/Outline file",
                           parameters.geometry.outline_file);
      if (parameters.geometry.outline == Outline::gmsh)
        files.emplace_back("Geometry/Mesh file", parameters.geometry.mesh_file);
      for (const contact::ToolDefinition &tool :
           model->contact().tool_definitions())
        if (tool.geometry == "file" || tool.geometry == "cad")
          files.emplace_back(tool.parameter_prefix + "File", tool.file);
      return files;
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
      checkpoint.state          = model->whole_state();
      checkpoint.table_sizes    = table_sizes;
      checkpoint.postprocessors = postprocessors.save();
      checkpoint.input_files    = input_files;
      state::write_checkpoint(state::checkpoint_file(
                                parameters.output.output_directory),
                              checkpoint);
    }


    void
    FormingProblem::restore_checkpoint(const bool cut_tables)
    {
      const std::string &directory  = parameters.output.output_directory;
      const std::string  filename   = state::checkpoint_file(directory);
      state::Checkpoint  checkpoint = state::read_checkpoint(filename);
      std::vector<state::StageRange> ranges;
      for (const process::Stage &stage : parameters.stages)
        ranges.push_back({stage.start_load,
                          stage.end_load,
                          stage.load_stepping.maximum_increment});
      state::check_resumable(checkpoint,
                             filename,
                             parameters.listing,
                             parameters.default_listing,
                             ranges,
                             input_files);
      try
      {
        model->restore(std::move(checkpoint.state));
        increments->reset_unknowns();
        postprocessors.initialize(*view);
        postprocessors.load(checkpoint.postprocessors);
      }
      catch (const std::runtime_error &error)
      {
        // InputError of the model's sizes, or a post-processor's data that
        // is not its own.
        std::string what = error.what();
        if (what.rfind("--resume: ", 0) == 0)
          what = what.substr(10);
        throw InputError("--resume: " + filename
                         + " does not fit this model: " + what);
      }
      // Every check made, the output directory is touched only now.
      state::check_tables(directory, checkpoint.table_sizes);
      if (cut_tables)
        state::truncate_tables(directory, checkpoint.table_sizes);
    }


    void
    FormingProblem::check_resume()
    {
      restore_checkpoint(false);
    }
  } // namespace problem
} // namespace deepdraw
