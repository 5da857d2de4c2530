#include <deepdraw/io/binary_stream.h>
#include <deepdraw/io/output_error.h>
#include <deepdraw/io/output_file.h>
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
      std::size_t n = 0;
      read_value(stream, n, source);
      std::vector<PvdRecord::Entry> entries;
      for (std::size_t i = 0; i < n && stream; ++i)
      {
        PvdRecord::Entry entry;
        read_value(stream, entry.time, source);
        read_value(stream, entry.part, source);
        entry.file = read_string(stream, source);
        entries.push_back(entry);
      }
      return entries;
    }
  } // namespace io
} // namespace deepdraw
