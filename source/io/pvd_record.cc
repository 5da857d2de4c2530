#include <cmath>
#include <deepdraw/io/binary_stream.h>
#include <deepdraw/io/output_directory.h>
#include <deepdraw/io/output_error.h>
#include <deepdraw/io/output_file.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/pvd_record.h>
#include <iomanip>
#include <sstream>

namespace deepdraw
{
  namespace io
  {
    PvdRecord::PvdRecord(const std::string        &filename,
                         const std::vector<Entry> &entries)
        : filename(filename)
        , entries(entries)
    {
    }


    const std::vector<PvdRecord::Entry> &
    PvdRecord::steps() const
    {
      return entries;
    }


    void
    PvdRecord::add_step(const double                    time,
                        const std::vector<std::string> &parts)
    {
      check_finite_for_output(&time,
                              &time + 1,
                              "the time of a step of " + filename);
      for (unsigned int p = 0; p < parts.size(); ++p)
        entries.push_back({time, p, parts[p]});

      std::ostringstream out;
      out << std::setprecision(12)
          << "<?xml version=\"1.0\"?>\n"
             "<VTKFile type=\"Collection\" version=\"0.1\" "
             "byte_order=\"LittleEndian\">\n"
             "  <Collection>\n";
      for (const Entry &entry : entries)
        out << "    <DataSet timestep=\"" << entry.time
            << "\" group=\"\" part=\"" << entry.part << "\" file=\""
            << entry.file << "\"/>\n";
      out << "  </Collection>\n</VTKFile>\n";
      write_file_atomically(filename, out.str());
    }


    void
    write_entries(std::ostream                        &stream,
                  const std::vector<PvdRecord::Entry> &entries)
    {
      write_value(stream, entries.size());
      for (const PvdRecord::Entry &entry : entries)
      {
        write_value(stream, entry.time);
        write_value(stream, entry.part);
        write_string(stream, entry.file);
      }
    }


    std::vector<PvdRecord::Entry>
    read_entries(std::istream &stream, const std::string &source)
    {
      // A count bounded by the bytes left, a finite time and a plain file
      // name (the VTU files are in the PVD file's directory).
      const std::size_t n
        = read_count(stream,
                     sizeof(double) + sizeof(unsigned) + sizeof(std::size_t),
                     source,
                     "PVD steps");
      std::vector<PvdRecord::Entry> entries;
      for (std::size_t i = 0; i < n; ++i)
      {
        PvdRecord::Entry entry;
        read_value(stream, entry.time, source);
        read_value(stream, entry.part, source);
        entry.file = read_string(stream, source);
        if (!std::isfinite(entry.time) || !is_plain_file_name(entry.file))
          throw std::runtime_error("PVD steps: a step at time "
                                   + std::to_string(entry.time) + " of '"
                                   + one_line(entry.file)
                                   + "' (a finite time and a plain file "
                                     "name are needed)");
        entries.push_back(entry);
      }
      return entries;
    }
  } // namespace io
} // namespace deepdraw
