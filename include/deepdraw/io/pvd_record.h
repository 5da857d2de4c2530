// The ParaView collection solution.pvd: one dataset per output step (time =
// load parameter), each step possibly made of several VTU parts (the sheet,
// the tools). Rewritten atomically after every output step.
#ifndef deepdraw_io_pvd_record_h
#define deepdraw_io_pvd_record_h

#include <iosfwd>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace io
  {
    class PvdRecord
    {
    public:
      struct Entry
      {
        double      time;
        unsigned    part;
        std::string file;
      };

      // A record with the given steps already in it (a resumed run); the
      // file is written at the next add_step().
      explicit PvdRecord(const std::string        &filename,
                         const std::vector<Entry> &entries = {});
      // Adds the VTU files (names relative to the .pvd) of one output step.
      void
      add_step(double time, const std::vector<std::string> &parts);
      const std::vector<Entry> &
      steps() const;

    private:
      std::string        filename;
      std::vector<Entry> entries;
    };

    // The entries as a binary image (a checkpoint), and back; read throws
    // std::runtime_error naming source if the stream is cut short.
    void
    write_entries(std::ostream                        &stream,
                  const std::vector<PvdRecord::Entry> &entries);
    std::vector<PvdRecord::Entry>
    read_entries(std::istream &stream, const std::string &source);
  } // namespace io
} // namespace deepdraw

#endif
