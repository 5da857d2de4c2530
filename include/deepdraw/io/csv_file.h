// A CSV table written row by row: each row is complete and flushed when it
// is added, so a run that stops leaves a valid file with every converged
// increment in it.
#ifndef deepdraw_io_csv_file_h
#define deepdraw_io_csv_file_h

#include <fstream>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace io
  {
    class CsvFile
    {
    public:
      CsvFile() = default;
      CsvFile(const std::string              &filename,
              const std::vector<std::string> &columns);
      // With append, the file must exist with this header (a resumed run):
      // rows are added after its last one.
      void
      open(const std::string              &filename,
           const std::vector<std::string> &columns,
           bool                            append = false);
      // Numbers with 10 significant digits; throws if the count is wrong.
      void
      add_row(const std::vector<double> &values);

    private:
      std::ofstream file;
      std::string   filename;
      std::size_t   n_columns = 0;
    };

    // Writes content to filename through a temporary file and a rename, so
    // that the file on disk is always either the old or the new version.
    void
    write_file_atomically(const std::string &filename,
                          const std::string &content);

    // A whole table (the format of CsvFile) written at once, atomically:
    // for results that are complete only when all rows are known.
    void
    write_csv_file_atomically(const std::string                      &filename,
                              const std::vector<std::string>         &columns,
                              const std::vector<std::vector<double>> &rows);
  } // namespace io
} // namespace deepdraw

#endif
