// Checkpoint and restart of FormingProblem (doc/user_guide.md §6, D55,
// D101): the committed state with its stage, the parameters and the
// output progress; a resumed run continues the same arithmetic from there.
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/problem/forming_problem.h>
#include <sstream>

namespace deepdraw
{
  namespace problem
  {
    void
    FormingProblem::save_checkpoint() const
    {
      state::Checkpoint checkpoint;
      checkpoint.parameters     = parameters.listing;
      checkpoint.state          = committed;
      checkpoint.table_sizes    = table_sizes;
      checkpoint.postprocessors = postprocessors.save();
      state::write_checkpoint(state::checkpoint_file(
                                parameters.output.output_directory),
                              checkpoint);
    }


    namespace
    {
      // The checkpointed state must belong to this mesh and contact set-up.
      void
      check_size(const std::string &what,
                 const std::size_t  checkpointed,
                 const std::size_t  expected)
      {
        if (checkpointed != expected)
          throw InputError("--resume: the checkpoint has "
                           + std::to_string(checkpointed) + " " + what
                           + ", this model " + std::to_string(expected));
      }
    } // namespace


    void
    FormingProblem::restore_checkpoint()
    {
      const std::string      &directory  = parameters.output.output_directory;
      const std::string       filename   = state::checkpoint_file(directory);
      state::Checkpoint       checkpoint = state::read_checkpoint(filename);
      state::SimulationState &saved      = checkpoint.state;
      if (saved.stage >= parameters.stages.size())
        throw InputError("--resume: " + filename + " was written in stage "
                         + std::to_string(saved.stage + 1)
                         + ", but the "
                           "process has "
                         + std::to_string(parameters.stages.size())
                         + " stage(s)");

      const std::vector<std::string> changes
        = state::changed_model_parameters(checkpoint.parameters,
                                          parameters.listing,
                                          parameters.default_listing,
                                          saved.stage);
      if (!changes.empty())
      {
        std::ostringstream message;
        message << "--resume: " << filename
                << " was written for another model; changed parameters:";
        for (const std::string &change : changes)
          message << "\n  " << change;
        message << "\n(only the subsections Output and Checkpoint, the "
                   "stopping parameters Process/Final load, Load stepping/"
                   "Minimum increment and Load stepping/Maximum cut-backs, "
                   "and the stages after the checkpoint's may change on a "
                   "resume)";
        throw InputError(message.str());
      }
      // The mesh is rebuilt from the prm; an adaptive run's refinements
      // are replayed on it (D84), and the stage's tools and constraints
      // set up.
      if (!saved.refinements.empty())
        discretisation.replay_refinements(saved.refinements);
      committed.stage = saved.stage;
      contact_coupling.begin_stage(saved.stage);
      set_up_system();
      check_size("vertices",
                 saved.vertices.size(),
                 discretisation.triangulation().n_vertices());
      check_size("displacement unknowns",
                 saved.total_displacement.size(),
                 discretisation.n_displacement_dofs());
      check_size("Newton unknowns",
                 saved.converged_solution.size(),
                 newton_unknowns.size());
      // Against the mesh (the refinements replayed), not the initial state.
      const std::size_t n_cells
        = discretisation.triangulation().n_active_cells();
      check_size("quadrature points",
                 saved.history.size(),
                 n_cells * fe::n_weighted_points);
      check_size("cells with enhanced parameters",
                 saved.enhanced_parameters.size(),
                 committed.enhanced_parameters.empty() ? 0 : n_cells);
      if (contact_coupling.active())
        contact_coupling.restore(saved.contact);

      state::truncate_tables(directory, checkpoint.table_sizes);
      committed = std::move(saved);
      // The configuration x_t of the checkpoint (updated Lagrangian).
      discretisation.set_vertices(committed.vertices);
      thickness_measurement.update(discretisation.triangulation(),
                                   parameters.geometry.thickness);
      trial_history             = committed.history;
      trial_enhanced_parameters = committed.enhanced_parameters;
      newton_unknowns           = committed.converged_solution;
      postprocessors.load(checkpoint.postprocessors);
    }
  } // namespace problem
} // namespace deepdraw
