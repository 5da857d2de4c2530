// Checkpoint and restart (doc/user_guide.md §6, doc/decisions.md D55,
// D160): the SimulationState, the model's parameters, how far the output
// files got and the digests of the input files, in one binary file with a
// CRC-32 over its content, written through a temporary name and a rename,
// so that a run killed at any moment leaves either the previous checkpoint
// or the new one. A checkpoint is verified whole (checksum, every field in
// range, every file name plain) before a resume touches anything.
#ifndef deepdraw_state_checkpoint_h
#define deepdraw_state_checkpoint_h

#include <cstdint>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/io/checksum.h>
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

    // A file the model reads: the parameter that names it
    // ("Contact/Tool 1/File"), its path and its digest when the run began.
    struct InputFile
    {
      std::string    parameter;
      std::string    path;
      io::FileDigest digest;
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
      // Every file the model reads besides the prm (tool, outline and mesh
      // files), by the parameter that names it: a resume refuses a file
      // that changed (D161). Empty in checkpoints before format 4.
      std::vector<InputFile> input_files;
    };

    // The checkpoint file of a run writing to output_directory.
    std::string
    checkpoint_file(const std::string &output_directory);

    // Throws std::runtime_error naming the file if it cannot be written
    // (the previous checkpoint then stays, and no temporary file).
    void
    write_checkpoint(const std::string &filename, const Checkpoint &checkpoint);
    // Throws InputError naming the file and the field if it is missing,
    // not a whole checkpoint, its checksum does not match (format 4), or a
    // field is out of range: a count beyond the file's size, a value that
    // is not finite, a next increment that is not positive, a table name
    // that is not a plain *.csv name (D160). A checkpoint of the format
    // before stages and post-processors (D101) is read as one of the first
    // stage; formats 1 to 3 have no checksum.
    Checkpoint
    read_checkpoint(const std::string &filename);

    // The same from the bytes of a file (the fuzz target).
    Checkpoint
    parse_checkpoint(const std::string &bytes, const std::string &filename);

    // Writes the checksummed image of a checkpoint (what write_checkpoint
    // writes) to a stream; throws std::runtime_error if the state cannot be
    // written.
    void
    write_checkpoint_image(std::ostream &stream, const Checkpoint &checkpoint);

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

    // The InputFile of each (parameter, path), its digest taken now;
    // throws InputError naming the parameter and the file if one cannot be
    // read.
    std::vector<InputFile>
    digest_input_files(
      const std::vector<std::pair<std::string, std::string>> &files);

    // What a checkpoint's load must fit: per stage its load range and its
    // largest increment.
    struct StageRange
    {
      double start_load        = 0.;
      double end_load          = 1.;
      double maximum_increment = 1.;
    };

    // Throws InputError naming the checkpoint file if the checkpoint does
    // not belong to the model of the flattened parameters `listing` (with
    // their `defaults`) and its stages: a stage it does not have, a load
    // outside the stage's range or a next increment above its largest,
    // changed parameters (changed_model_parameters), listed, or an input
    // file whose digest differs from the checkpoint's (current_files: the
    // files of this model).
    void
    check_resumable(const Checkpoint              &checkpoint,
                    const std::string             &filename,
                    const std::string             &listing,
                    const std::string             &defaults,
                    const std::vector<StageRange> &stages,
                    const std::vector<InputFile>  &current_files);

    // Sizes of the *.csv files in directory (names relative to it).
    std::vector<std::pair<std::string, std::uintmax_t>>
    csv_table_sizes(const std::string &directory);
    // Throws InputError if a table is missing, not a regular file (a link)
    // or shorter than its recorded size (it was not written by this run).
    void
    check_tables(
      const std::string                                         &directory,
      const std::vector<std::pair<std::string, std::uintmax_t>> &sizes);
    // Cuts each table back to its recorded size, after check_tables.
    void
    truncate_tables(
      const std::string                                         &directory,
      const std::vector<std::pair<std::string, std::uintmax_t>> &sizes);
  } // namespace state
} // namespace deepdraw

#endif
