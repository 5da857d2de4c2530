// Checkpoint and restart (doc/user_guide.md §6, doc/decisions.md D55): the
// SimulationState, the model's parameters and how far the output files got,
// in one binary file written through a temporary name and a rename, so that
// a run killed at any moment leaves either the previous checkpoint or the
// new one.
#ifndef deepdraw_state_checkpoint_h
#define deepdraw_state_checkpoint_h

#include <cstdint>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/state/simulation_state.h>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace deepdraw
{
  namespace state
  {
    using namespace dealii;

    // subsection Checkpoint.
    struct CheckpointParameters
    {
      // Converged increments between checkpoints; 0: only at a clean stop
      // (a signal, a failed run).
      unsigned int interval = 0;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    struct Checkpoint
    {
      // The model's parameters, as flatten_parameters() writes them.
      std::string     parameters;
      SimulationState state;
      // The byte size of every CSV table at the checkpoint (a resumed run
      // cuts the tables back to these sizes and appends to them).
      std::vector<std::pair<std::string, std::uintmax_t>> table_sizes;
      // What each post-processor keeps (postprocess::Interface::save), by
      // its name.
      std::map<std::string, std::string> postprocessors;
    };

    // The checkpoint file of a run writing to output_directory.
    std::string
    checkpoint_file(const std::string &output_directory);

    // Throws std::runtime_error naming the file if it cannot be written
    // (the previous checkpoint then stays).
    void
    write_checkpoint(const std::string &filename, const Checkpoint &checkpoint);
    // Throws InputError naming the file if it is missing or not a whole
    // checkpoint. A checkpoint of the format before stages and
    // post-processors (D101) is read as one of the first stage.
    Checkpoint
    read_checkpoint(const std::string &filename);

    // Every parameter as "Subsection/Name = value", one per line, in
    // declaration order.
    std::string
    flatten_parameters(const ParameterHandler &prm);

    // The parameters whose values differ between two flattened listings,
    // as "Subsection/Name: old -> new", leaving out those a resumed run may
    // change: subsections Output and Checkpoint, the stopping parameters
    // Process/Final load, Load stepping/Minimum increment and Load
    // stepping/Maximum cut-backs (D55), and those of the stages after
    // `stage` (0 the first; D101). A parameter the checkpoint does not have
    // (it is newer) counts as unchanged if it has its value of `defaults`.
    std::vector<std::string>
    changed_model_parameters(const std::string &checkpointed,
                             const std::string &current,
                             const std::string &defaults,
                             unsigned int       stage);

    // Throws InputError naming the checkpoint file if the checkpoint does
    // not belong to the model of the flattened parameters `listing` (with
    // their `defaults`) and its n_stages stages: a stage it does not have,
    // or changed parameters (changed_model_parameters), listed.
    void
    check_resumable(const Checkpoint  &checkpoint,
                    const std::string &filename,
                    const std::string &listing,
                    const std::string &defaults,
                    unsigned int       n_stages);

    // Sizes of the *.csv files in directory (names relative to it).
    std::vector<std::pair<std::string, std::uintmax_t>>
    csv_table_sizes(const std::string &directory);
    // Cuts each table back to its recorded size; throws InputError if one
    // is missing or shorter (it was not written by this run).
    void
    truncate_tables(
      const std::string                                         &directory,
      const std::vector<std::pair<std::string, std::uintmax_t>> &sizes);
  } // namespace state
} // namespace deepdraw

#endif
