#include <algorithm>
#include <cstdlib>
#include <deepdraw/io/binary_stream.h>
#include <deepdraw/io/checksum.h>
#include <deepdraw/io/checksummed_output.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/memory_input.h>
#include <deepdraw/io/output_directory.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/pvd_record.h>
#include <deepdraw/io/regular_file.h>
#include <deepdraw/io/writing_rank.h>
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
      // Format 4 (D160): the layout of format 3, the input files' digests
      // after the post-processors' data, and the CRC-32 of every byte
      // before it (the tag included) as the file's last 4 bytes.
      constexpr char tag[] = "deepdraw-checkpoint-4";
      // Before input digests and the checksum (D160).
      constexpr char tag_before_checksum[] = "deepdraw-checkpoint-3";
      // Before releases (D150): the same layout, its state of format 4
      // (SimulationState::read tells them apart).
      constexpr char tag_before_release[] = "deepdraw-checkpoint-2";
      // Before stages and post-processors (D101): the output progress was
      // the VTU counter and the PVD steps, now the "visualization"
      // post-processor's data, then the table sizes.
      constexpr char tag_before_stages[] = "deepdraw-checkpoint-1";
      static_assert(sizeof(tag) == sizeof(tag_before_checksum));
      static_assert(sizeof(tag) == sizeof(tag_before_release));
      static_assert(sizeof(tag) == sizeof(tag_before_stages));
      constexpr std::size_t checksum_size = sizeof(std::uint32_t);

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

      // A table name must be a plain *.csv name: a resume cuts these files
      // back, and only in the output directory.
      std::vector<std::pair<std::string, std::uintmax_t>>
      read_table_sizes(std::istream &stream)
      {
        std::vector<std::pair<std::string, std::uintmax_t>> sizes;
        const std::size_t n = io::read_count(stream,
                                             2 * sizeof(std::size_t),
                                             source,
                                             "table sizes");
        for (std::size_t i = 0; i < n; ++i)
        {
          std::string    name = io::read_string(stream, source);
          std::uintmax_t size = 0;
          get(stream, size);
          const std::string printed = io::one_line(name);
          if (!io::is_plain_file_name(name) || name.size() < 5
              || name.compare(name.size() - 4, 4, ".csv") != 0)
            throw std::runtime_error("table name '" + printed
                                     + "' is not a plain *.csv file name "
                                       "in the output directory");
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

      void
      read_postprocessors(std::istream &stream, Checkpoint &checkpoint)
      {
        const std::size_t n = io::read_count(stream,
                                             2 * sizeof(std::size_t),
                                             source,
                                             "post-processors");
        for (std::size_t i = 0; i < n; ++i)
        {
          const std::string name          = io::read_string(stream, source);
          checkpoint.postprocessors[name] = io::read_string(stream, source);
        }
      }

      void
      write_input_files(std::ostream                 &stream,
                        const std::vector<InputFile> &files)
      {
        put(stream, files.size());
        for (const InputFile &file : files)
        {
          io::write_string(stream, file.parameter);
          io::write_string(stream, file.path);
          put(stream, file.digest.size);
          put(stream, file.digest.crc);
        }
      }

      std::vector<InputFile>
      read_input_files(std::istream &stream)
      {
        const std::size_t n
          = io::read_count(stream,
                           2 * sizeof(std::size_t) + sizeof(std::uint64_t)
                             + sizeof(std::uint32_t),
                           source,
                           "input files");
        std::vector<InputFile> files(n);
        for (InputFile &file : files)
        {
          file.parameter = io::read_string(stream, source);
          file.path      = io::read_string(stream, source);
          get(stream, file.digest.size);
          get(stream, file.digest.crc);
        }
        return files;
      }

      // The fields after the tag, as the tag's format has them.
      void
      read_fields(std::istream      &stream,
                  const std::string &read_tag,
                  Checkpoint        &checkpoint)
      {
        checkpoint.parameters = io::read_string(stream, source);
        checkpoint.state.read(stream);
        if (read_tag == tag_before_stages)
          read_output_progress(stream, checkpoint);
        else
        {
          checkpoint.table_sizes = read_table_sizes(stream);
          read_postprocessors(stream, checkpoint);
        }
        if (read_tag == tag)
          checkpoint.input_files = read_input_files(stream);
        if (stream.peek() != std::char_traits<char>::eof())
          throw std::runtime_error("bytes after the last field");
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
                        "(SIGINT, SIGTERM, SIGHUP, SIGQUIT, a failed "
                        "increment).");
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
    write_checkpoint_image(std::ostream &target, const Checkpoint &checkpoint)
    {
      // Straight to the target, the CRC-32 taken on the way: no image of
      // the whole checkpoint in memory (D221).
      io::ChecksummedOutput stream(target);
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
      write_input_files(stream, checkpoint.input_files);
      const std::uint32_t crc = stream.crc();
      target.write(reinterpret_cast<const char *>(&crc), sizeof(crc));
      // A write that failed on the way (a full disk) fails the target.
      if (!stream)
        target.setstate(std::ios::badbit);
    }


    void
    write_checkpoint(const std::string &filename, const Checkpoint &checkpoint)
    {
      if (!io::writes_files())
        return;
      const std::string temporary = filename + ".tmp";
      {
        std::ofstream stream(temporary, std::ios::binary);
        try
        {
          write_checkpoint_image(stream, checkpoint);
        }
        catch (const std::runtime_error &)
        {
          // The state's writer found the stream failed: said below.
          stream.setstate(std::ios::badbit);
        }
        catch (...)
        {
          stream.close();
          std::error_code ignored;
          std::filesystem::remove(temporary, ignored);
          throw;
        }
        stream.flush();
        if (!stream)
        {
          stream.close();
          std::filesystem::remove(temporary);
          throw std::runtime_error("cannot write the checkpoint " + temporary);
        }
      }
      std::error_code error;
      std::filesystem::rename(temporary, filename, error);
      if (error)
      {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw std::runtime_error("cannot rename " + temporary + " to "
                                 + filename + ": " + error.message());
      }
    }


    Checkpoint
    parse_checkpoint(const std::string &bytes, const std::string &filename)
    {
      Checkpoint checkpoint;
      try
      {
        const std::string read_tag(bytes.data(),
                                   std::min(bytes.size(), sizeof(tag)));
        const bool with_checksum = read_tag == std::string(tag, sizeof(tag));
        if (!with_checksum
            && read_tag != std::string(tag_before_checksum, sizeof(tag))
            && read_tag != std::string(tag_before_release, sizeof(tag))
            && read_tag != std::string(tag_before_stages, sizeof(tag)))
          throw std::runtime_error("not a deepdraw checkpoint");
        std::size_t content = bytes.size();
        if (with_checksum)
        {
          if (content < sizeof(tag) + checksum_size)
            throw std::runtime_error("the file ends early");
          content -= checksum_size;
          std::uint32_t stored = 0;
          std::copy_n(bytes.data() + content,
                      checksum_size,
                      reinterpret_cast<char *>(&stored));
          if (io::crc32(bytes.data(), content) != stored)
            throw std::runtime_error(
              "checksum: the CRC-32 of its content does not match the one "
              "stored in it (the file was changed or damaged after it was "
              "written)");
        }
        // Parsed where it lies: no copy of the file's bytes (D221).
        io::MemoryInput stream(bytes.data() + sizeof(tag),
                               content - sizeof(tag));
        read_fields(stream, read_tag.c_str(), checkpoint);
      }
      catch (const std::runtime_error &error)
      {
        throw InputError("--resume: " + filename
                         + " is not a usable checkpoint: "
                         + io::one_line(error.what()));
      }
      return checkpoint;
    }


    Checkpoint
    read_checkpoint(const std::string &filename)
    {
      std::error_code error;
      const auto      status = std::filesystem::status(filename, error);
      std::ifstream   stream;
      if (std::filesystem::exists(status))
        io::check_regular_file(filename, "checkpoint");
      if (std::filesystem::is_regular_file(status))
        stream.open(filename, std::ios::binary);
      if (!stream.is_open() || !stream)
        throw InputError("--resume: there is no checkpoint " + filename
                         + " (checkpoints are written every Checkpoint/"
                           "Interval increments, at the end of every stage "
                           "but the last, and at a clean stop)");
      // Read once into a string of the file's size (D221).
      std::string bytes;
      stream.seekg(0, std::ios::end);
      const std::streamoff size = stream.tellg();
      stream.seekg(0, std::ios::beg);
      if (size > 0)
      {
        bytes.resize(std::size_t(size));
        stream.read(bytes.data(), size);
      }
      if (size < 0 || !stream)
        throw InputError("--resume: cannot read the checkpoint " + filename);
      return parse_checkpoint(bytes, filename);
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


  } // namespace state
} // namespace deepdraw
