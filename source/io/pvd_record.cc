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
  } // namespace io
} // namespace deepdraw
