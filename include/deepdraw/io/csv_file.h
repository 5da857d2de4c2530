// A CSV table written row by row: each row is formatted completely and
// handed to the kernel with one write; a write that fails or is cut short
// is undone (the file is truncated to the last whole row) and reported as
// io::OutputError. So a run that stops, even on a full disk, leaves a valid
// file with every row that was reported written (doc/user_guide.md §3).
#ifndef deepdraw_io_csv_file_h
#define deepdraw_io_csv_file_h

#include <deepdraw/io/output_file.h>
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
      CsvFile(const CsvFile &) = delete;
      CsvFile &
      operator=(const CsvFile &)
        = delete;
      ~CsvFile();

      // Creates (truncates) the file and writes the header row; with
      // append, the file must exist with this header (a resumed run) and
      // rows are added after its last one.
      void
      open(const std::string              &filename,
           const std::vector<std::string> &columns,
           bool                            append = false);
      // Numbers with 10 significant digits. Throws std::logic_error if the
      // count is wrong, io::OutputError if a value is not finite (nothing
      // of the row is written) or the write fails.
      void
      add_row(const std::vector<double> &values);
      // Closes the file, reporting a failed close (some file systems report
      // a full disk only there). The destructor closes silently.
      void
      close();
      // Closes without reporting anything (after another error).
      void
      close_silently();

    private:
      void
      write_row(const std::string &row);

      int                      descriptor = -1;
      std::string              filename;
      std::vector<std::string> columns;
      // Bytes of whole rows in the file.
      long long size = 0;
    };

    // A whole table (the format of CsvFile) written at once, atomically:
    // for results that are complete only when all rows are known.
    void
    write_csv_file_atomically(const std::string                      &filename,
                              const std::vector<std::string>         &columns,
                              const std::vector<std::vector<double>> &rows);
  } // namespace io
} // namespace deepdraw

#endif
