// The checks of a resume (doc/user_guide.md §6, D55, D160, D161): the
// model's parameters, its input files, the stage and load of the
// checkpoint, and the output tables, all before anything is touched.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <deepdraw/io/checksum.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/writing_rank.h>
#include <deepdraw/state/checkpoint.h>
#include <filesystem>
#include <map>
#include <sstream>

namespace deepdraw
{
  namespace state
  {
    namespace
    {
      // "Subsection/Name" -> value, from a flatten_parameters() listing.
      std::map<std::string, std::string>
      parse_listing(const std::string &listing)
      {
        std::map<std::string, std::string> values;
        std::istringstream                 lines(listing);
        std::string                        line;
        while (std::getline(lines, line))
        {
          const auto separator = line.find(" = ");
          if (separator != std::string::npos)
            values[line.substr(0, separator)] = line.substr(separator + 3);
        }
        return values;
      }

      // Parameters a resumed run may change (D55), and those of the stages
      // after the checkpoint's (D101).
      bool
      may_change_on_resume(const std::string &name, const unsigned int stage)
      {
        const std::string stage_slot = "Process/Stage ";
        if (name.rfind(stage_slot, 0) == 0
            && std::atoi(name.c_str() + stage_slot.size()) > int(stage) + 1)
          return true;
        return name.rfind("Output/", 0) == 0
               || name.rfind("Checkpoint/", 0) == 0
               || name == "Process/Final load"
               || name == "Load stepping/Minimum increment"
               || name == "Load stepping/Maximum cut-backs";
      }

      // Every input file the checkpoint recorded must have its digest
      // still, under the same parameter (D161); a file of this model the
      // checkpoint does not know is a changed parameter, reported there.
      void
      check_input_files(const std::vector<InputFile> &recorded,
                        const std::vector<InputFile> &current,
                        const std::string            &filename)
      {
        for (const InputFile &old_file : recorded)
          for (const InputFile &file : current)
            if (file.parameter == old_file.parameter
                && !(file.digest == old_file.digest))
              throw InputError(
                "--resume: the input file " + io::one_line(file.path) + " ("
                + file.parameter + ") changed after " + filename
                + " was written (" + std::to_string(old_file.digest.size)
                + " bytes then, " + std::to_string(file.digest.size)
                + " now; CRC-32 differs); a resumed run must read the "
                  "files the run began with");
      }

      // The load of the checkpoint must lie in its stage's range, its next
      // step at most the stage's largest increment (D160).
      void
      check_load(const SimulationState &state,
                 const StageRange      &range,
                 const std::string     &filename)
      {
        const double tolerance = 1e-9 * std::max(1., std::abs(range.end_load));
        if (!(state.load >= range.start_load - tolerance
              && state.load <= range.end_load + tolerance))
          throw InputError(
            "--resume: " + filename + ": load = " + io::to_string(state.load)
            + " lies outside stage " + std::to_string(state.stage + 1)
            + "'s range " + io::to_string(range.start_load) + " to "
            + io::to_string(range.end_load)
            + " (a damaged checkpoint, or a Final load below the load it "
              "was written at)");
        if (!(state.next_increment <= range.maximum_increment * (1. + 1e-9)))
          throw InputError("--resume: " + filename + ": next increment = "
                           + io::to_string(state.next_increment)
                           + " is larger than the stage's Maximum "
                             "increment "
                           + io::to_string(range.maximum_increment));
      }
    } // namespace


    std::vector<std::string>
    changed_model_parameters(const std::string &checkpointed,
                             const std::string &current,
                             const std::string &defaults,
                             const unsigned int stage)
    {
      const auto               old_values     = parse_listing(checkpointed);
      const auto               new_values     = parse_listing(current);
      const auto               default_values = parse_listing(defaults);
      std::vector<std::string> changes;
      for (const auto &[name, value] : new_values)
      {
        if (may_change_on_resume(name, stage))
          continue;
        const auto old           = old_values.find(name);
        const auto default_value = default_values.find(name);
        if (old == old_values.end())
        {
          // A parameter younger than the checkpoint, at its default: the
          // model as it was.
          if (default_value == default_values.end()
              || default_value->second != value)
            changes.push_back(name + ": not in the checkpoint");
        }
        else if (old->second != value)
          changes.push_back(name + ": " + old->second + " -> " + value);
      }
      for (const auto &[name, value] : old_values)
        if (!may_change_on_resume(name, stage) && new_values.count(name) == 0)
          changes.push_back(name + ": no longer a parameter");
      return changes;
    }


    void
    check_resumable(const Checkpoint              &checkpoint,
                    const std::string             &filename,
                    const std::string             &listing,
                    const std::string             &defaults,
                    const std::vector<StageRange> &stages,
                    const std::vector<InputFile>  &current_files)
    {
      const unsigned int stage = checkpoint.state.stage;
      if (stage >= stages.size())
        throw InputError("--resume: " + filename + " was written in stage "
                         + std::to_string(stage + 1) + ", but the process has "
                         + std::to_string(stages.size()) + " stage(s)");
      const std::vector<std::string> changes
        = changed_model_parameters(checkpoint.parameters,
                                   listing,
                                   defaults,
                                   stage);
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
      check_input_files(checkpoint.input_files, current_files, filename);
      check_load(checkpoint.state, stages[stage], filename);
    }


    std::vector<std::pair<std::string, std::uintmax_t>>
    csv_table_sizes(const std::string &directory)
    {
      std::vector<std::pair<std::string, std::uintmax_t>> sizes;
      if (!io::writes_files())
        return sizes;
      for (const auto &entry : std::filesystem::directory_iterator(directory))
        if (entry.is_regular_file() && entry.path().extension() == ".csv")
          sizes.emplace_back(entry.path().filename().string(),
                             entry.file_size());
      std::sort(sizes.begin(), sizes.end());
      return sizes;
    }


    void
    check_tables(
      const std::string                                         &directory,
      const std::vector<std::pair<std::string, std::uintmax_t>> &sizes)
    {
      for (const auto &[name, size] : sizes)
      {
        const std::string path = directory + "/" + name;
        std::error_code   error;
        const auto        status = std::filesystem::symlink_status(path, error);
        const bool regular = !error && std::filesystem::is_regular_file(status);
        const auto actual
          = regular ? std::filesystem::file_size(path, error) : 0;
        if (!regular || error || actual < size)
          throw InputError(
            "--resume: " + checkpoint_file(directory) + ": the table "
            + io::one_line(path)
            + (!regular || error ? " is missing or not a regular file"
                                 : " is shorter than at the checkpoint ("
                                     + std::to_string(actual) + " bytes, "
                                     + std::to_string(size) + " recorded)")
            + "; the output directory was changed after the checkpoint "
              "was written");
      }
    }


    void
    truncate_tables(
      const std::string                                         &directory,
      const std::vector<std::pair<std::string, std::uintmax_t>> &sizes)
    {
      if (!io::writes_files())
        return;
      check_tables(directory, sizes);
      for (const auto &[name, size] : sizes)
        std::filesystem::resize_file(directory + "/" + name, size);
    }


    std::vector<InputFile>
    digest_input_files(
      const std::vector<std::pair<std::string, std::string>> &files)
    {
      std::vector<InputFile> digests;
      for (const auto &[parameter, path] : files)
        try
        {
          digests.push_back({parameter, path, io::file_digest(path)});
        }
        catch (const std::runtime_error &error)
        {
          throw InputError(parameter + ": " + io::one_line(error.what()));
        }
      return digests;
    }
  } // namespace state
} // namespace deepdraw
