#include <algorithm>
#include <cstdlib>
#include <deepdraw/io/binary_stream.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/pvd_record.h>
#include <deepdraw/state/checkpoint.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace deepdraw
{
  namespace state
  {
    namespace
    {
      constexpr char tag[] = "deepdraw-checkpoint-3";
      // Before releases (D150): the same layout, its state of format 4
      // (SimulationState::read tells them apart).
      constexpr char tag_before_release[] = "deepdraw-checkpoint-2";
      static_assert(sizeof(tag) == sizeof(tag_before_release));
      // Before stages and post-processors (D101): the output progress was
      // the VTU counter and the PVD steps, now the "visualization"
      // post-processor's data, then the table sizes.
      constexpr char tag_before_stages[] = "deepdraw-checkpoint-1";
      static_assert(sizeof(tag) == sizeof(tag_before_stages));

      constexpr char source[] = "the file";

      template <typename T>
      void
      put(std::ostream &stream, const T &value)
      {
        io::write_value(stream, value);
      }

      template <typename T>
      void
      get(std::istream &stream, T &value)
      {
        io::read_value(stream, value, source);
      }

      void
      write_table_sizes(
        std::ostream                                              &stream,
        const std::vector<std::pair<std::string, std::uintmax_t>> &sizes)
      {
        put(stream, sizes.size());
        for (const auto &[name, size] : sizes)
        {
          io::write_string(stream, name);
          put(stream, size);
        }
      }

      std::vector<std::pair<std::string, std::uintmax_t>>
      read_table_sizes(std::istream &stream)
      {
        std::vector<std::pair<std::string, std::uintmax_t>> sizes;
        std::size_t                                         n = 0;
        get(stream, n);
        for (std::size_t i = 0; i < n && stream; ++i)
        {
          std::string    name = io::read_string(stream, source);
          std::uintmax_t size = 0;
          get(stream, size);
          sizes.emplace_back(name, size);
        }
        return sizes;
      }

      // The output progress of a checkpoint before stages: the VTU counter
      // and the PVD steps (the "visualization" post-processor's data, in
      // its format), then the table sizes.
      void
      read_output_progress(std::istream &stream, Checkpoint &checkpoint)
      {
        unsigned int output_step = 0;
        get(stream, output_step);
        const std::vector<io::PvdRecord::Entry> entries
          = io::read_entries(stream, source);
        std::ostringstream visualization;
        io::write_value(visualization, output_step);
        io::write_entries(visualization, entries);
        checkpoint.postprocessors["visualization"] = visualization.str();
        checkpoint.table_sizes                     = read_table_sizes(stream);
      }

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

      std::string
      trim(const std::string &text)
      {
        const auto first = text.find_first_not_of(" \t");
        if (first == std::string::npos)
          return "";
        const auto last = text.find_last_not_of(" \t");
        return text.substr(first, last - first + 1);
      }
    } // namespace


    void
    CheckpointParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Checkpoint");
      prm.declare_entry("Interval",
                        "0",
                        Patterns::Integer(0),
                        "Converged increments between checkpoints "
                        "(checkpoint.bin in the output directory, resumed "
                        "with --resume); 0 writes one only at a clean stop "
                        "(SIGINT, SIGTERM, a failed increment).");
      prm.leave_subsection();
    }


    void
    CheckpointParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Checkpoint");
      interval = prm.get_integer("Interval");
      prm.leave_subsection();
    }


    std::string
    checkpoint_file(const std::string &output_directory)
    {
      return output_directory + "/checkpoint.bin";
    }


    void
    write_checkpoint(const std::string &filename, const Checkpoint &checkpoint)
    {
      const std::string temporary = filename + ".tmp";
      {
        std::ofstream stream(temporary, std::ios::binary);
        stream.write(tag, sizeof(tag));
        io::write_string(stream, checkpoint.parameters);
        checkpoint.state.write(stream);
        write_table_sizes(stream, checkpoint.table_sizes);
        put(stream, checkpoint.postprocessors.size());
        for (const auto &[name, data] : checkpoint.postprocessors)
        {
          io::write_string(stream, name);
          io::write_string(stream, data);
        }
        stream.flush();
        if (!stream)
        {
          std::filesystem::remove(temporary);
          throw std::runtime_error("cannot write the checkpoint " + temporary);
        }
      }
      std::error_code error;
      std::filesystem::rename(temporary, filename, error);
      if (error)
        throw std::runtime_error("cannot rename " + temporary + " to "
                                 + filename + ": " + error.message());
    }


    Checkpoint
    read_checkpoint(const std::string &filename)
    {
      std::ifstream stream(filename, std::ios::binary);
      if (!stream)
        throw InputError("--resume: there is no checkpoint " + filename
                         + " (checkpoints are written every Checkpoint/"
                           "Interval increments, at the end of every stage "
                           "but the last, and at a clean stop)");
      Checkpoint checkpoint;
      try
      {
        char read_tag[sizeof(tag)] = {};
        stream.read(read_tag, sizeof(tag));
        const bool before_stages
          = stream && std::string(read_tag) == tag_before_stages;
        if (!stream
            || (std::string(read_tag) != tag
                && std::string(read_tag) != tag_before_release
                && !before_stages))
          throw std::runtime_error("not a deepdraw checkpoint");
        checkpoint.parameters = io::read_string(stream, source);
        checkpoint.state.read(stream);
        if (before_stages)
          read_output_progress(stream, checkpoint);
        else
        {
          checkpoint.table_sizes = read_table_sizes(stream);
          std::size_t n          = 0;
          get(stream, n);
          for (std::size_t i = 0; i < n && stream; ++i)
          {
            const std::string name          = io::read_string(stream, source);
            checkpoint.postprocessors[name] = io::read_string(stream, source);
          }
        }
      }
      catch (const std::runtime_error &error)
      {
        throw InputError("--resume: " + filename
                         + " is not a usable checkpoint: " + error.what());
      }
      return checkpoint;
    }


    std::string
    flatten_parameters(const ParameterHandler &prm)
    {
      std::ostringstream printed;
      prm.print_parameters(printed,
                           ParameterHandler::OutputStyle(
                             ParameterHandler::ShortPRM
                             | ParameterHandler::KeepDeclarationOrder));
      std::vector<std::string> path;
      std::ostringstream       listing;
      std::istringstream       lines(printed.str());
      std::string              line;
      while (std::getline(lines, line))
      {
        line = trim(line);
        if (line.rfind("subsection ", 0) == 0)
          path.push_back(trim(line.substr(11)));
        else if (line == "end" && !path.empty())
          path.pop_back();
        else if (line.rfind("set ", 0) == 0)
        {
          const auto  equal = line.find('=');
          std::string name;
          for (const std::string &section : path)
            name += section + "/";
          listing << name << trim(line.substr(4, equal - 4)) << " = "
                  << trim(line.substr(equal + 1)) << '\n';
        }
      }
      return listing.str();
    }


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
    check_resumable(const Checkpoint  &checkpoint,
                    const std::string &filename,
                    const std::string &listing,
                    const std::string &defaults,
                    const unsigned int n_stages)
    {
      const unsigned int stage = checkpoint.state.stage;
      if (stage >= n_stages)
        throw InputError("--resume: " + filename + " was written in stage "
                         + std::to_string(stage + 1) + ", but the process has "
                         + std::to_string(n_stages) + " stage(s)");
      const std::vector<std::string> changes
        = changed_model_parameters(checkpoint.parameters,
                                   listing,
                                   defaults,
                                   stage);
      if (changes.empty())
        return;
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


    std::vector<std::pair<std::string, std::uintmax_t>>
    csv_table_sizes(const std::string &directory)
    {
      std::vector<std::pair<std::string, std::uintmax_t>> sizes;
      for (const auto &entry : std::filesystem::directory_iterator(directory))
        if (entry.is_regular_file() && entry.path().extension() == ".csv")
          sizes.emplace_back(entry.path().filename().string(),
                             entry.file_size());
      std::sort(sizes.begin(), sizes.end());
      return sizes;
    }


    void
    truncate_tables(
      const std::string                                         &directory,
      const std::vector<std::pair<std::string, std::uintmax_t>> &sizes)
    {
      for (const auto &[name, size] : sizes)
      {
        const std::string path = directory + "/" + name;
        std::error_code   error;
        const auto        actual = std::filesystem::file_size(path, error);
        if (error || actual < size)
          throw InputError(
            "--resume: " + path
            + (error ? " is missing" : " is shorter than at the checkpoint")
            + "; the output directory was changed after the "
              "checkpoint was written");
        std::filesystem::resize_file(path, size);
      }
    }
  } // namespace state
} // namespace deepdraw
