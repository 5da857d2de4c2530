// state::Checkpoint and restart of FormingProblem (doc/user_guide.md §6, D55):
// the committed state::SimulationState, the parameter listing and the output
// progress; a resumed run continues the same arithmetic from there.
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
      const std::string    &directory = output_parameters.output_directory;
      state::OutputProgress output;
      output.output_step = output_step;
      if (pvd)
        output.pvd_entries = pvd->steps();
      output.table_sizes = committed_table_sizes;
      state::write_checkpoint(state::checkpoint_file(directory),
                              parameter_listing,
                              state,
                              output);
    }


    namespace
    {
      // The checkpointed state must belong to this mesh and contact set-up.
      void
      check_sizes(const std::string &what,
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
      const std::string &directory  = output_parameters.output_directory;
      const std::string  filename   = state::checkpoint_file(directory);
      state::Checkpoint  checkpoint = state::read_checkpoint(filename);

      const std::vector<std::string> changes
        = state::changed_model_parameters(checkpoint.parameters,
                                          parameter_listing);
      if (!changes.empty())
      {
        std::ostringstream message;
        message << "--resume: " << filename
                << " was written for another model; changed parameters:";
        for (const std::string &change : changes)
          message << "\n  " << change;
        message
          << "\n(only the subsections Output and state::Checkpoint and the "
             "stopping parameters Process/Final load, Load stepping/"
             "Minimum increment and Load stepping/Maximum cut-backs "
             "may change on a resume)";
        throw InputError(message.str());
      }
      state::SimulationState &saved = checkpoint.state;
      // The mesh is rebuilt from the prm; an adaptive run's refinements
      // are replayed on it (D84).
      if (!saved.refinements.empty())
        replay_refinements(saved.refinements);
      check_sizes("vertices",
                  saved.vertices.size(),
                  triangulation.n_vertices());
      check_sizes("displacement unknowns",
                  saved.total_displacement.size(),
                  dof_handler.n_dofs());
      check_sizes("Newton unknowns",
                  saved.converged_solution.size(),
                  newton_unknowns.size());
      // Against the mesh (the refinements replayed), not the initial state.
      const std::size_t n_cells = triangulation.n_active_cells();
      check_sizes("quadrature points",
                  saved.history.size(),
                  n_cells * fe::n_weighted_points);
      check_sizes("cells with enhanced parameters",
                  saved.enhanced_parameters.size(),
                  state.enhanced_parameters.empty() ? 0 : n_cells);
      if (contact.active())
        contact.restore(saved.contact);

      state::truncate_tables(directory, checkpoint.output.table_sizes);
      state = std::move(saved);
      // The configuration x_t of the checkpoint (updated Lagrangian).
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          cell->vertex(v) = state.vertices[cell->vertex_index(v)];
      trial_history             = state.history;
      trial_enhanced_parameters = state.enhanced_parameters;
      newton_unknowns           = state.converged_solution;
      output_step               = checkpoint.output.output_step;
      resumed_pvd_steps         = checkpoint.output.pvd_entries;
      update_cell_geometry();
      compute_thickness();
    }
  } // namespace problem
} // namespace deepdraw
