#include <cerrno>
#include <cmath>
#include <deepdraw/io/csv_file.h>
#include <deepdraw/io/output_error.h>
#include <deepdraw/io/writing_rank.h>
#include <fcntl.h>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace deepdraw
{
  namespace io
  {
    namespace
    {
      template <typename T>
      std::string
      format_row(const std::vector<T> &values)
      {
        std::ostringstream row;
        row << std::setprecision(10);
        for (std::size_t c = 0; c < values.size(); ++c)
          row << (c ? "," : "") << values[c];
        row << '\n';
        return row.str();
      }

      // A value that is not finite names its column instead of reaching
      // the file (doc/user_guide.md §3: no NaN or inf is written).
      void
      check_row(const std::vector<double>      &values,
                const std::vector<std::string> &columns,
                const std::string              &filename)
      {
        for (std::size_t c = 0; c < values.size(); ++c)
          if (!std::isfinite(values[c]))
          {
            std::ostringstream text;
            text << "a non-finite value (" << values[c] << ") in column "
                 << columns[c] << " of " << filename << " (row with "
                 << columns[0] << " = " << values[0]
                 << "); deepdraw writes no NaN or inf";
            throw OutputError(text.str());
          }
      }
    } // namespace


    CsvFile::CsvFile(const std::string              &filename,
                     const std::vector<std::string> &columns)
    {
      open(filename, columns);
    }


    CsvFile::~CsvFile()
    {
      if (descriptor >= 0)
        ::close(descriptor);
    }


    void
    CsvFile::open(const std::string              &name,
                  const std::vector<std::string> &column_names,
                  const bool                      append)
    {
      if (descriptor >= 0)
        ::close(descriptor);
      filename = name;
      columns  = column_names;
      size     = 0;
      if (!writes_files())
        return;
      // O_NONBLOCK: a named pipe put in place of the table fails to open
      // (ENXIO) instead of blocking (D164); regular files ignore it.
      if (append)
      {
        std::ifstream existing(filename);
        std::string   header;
        if (!std::getline(existing, header)
            || header + '\n' != format_row(columns))
          throw OutputError(filename
                            + " does not have the columns of this run");
        descriptor = ::open(filename.c_str(), O_WRONLY | O_NONBLOCK);
        if (descriptor < 0)
          throw OutputError(describe_system_error(errno, "opening", filename));
        size = ::lseek(descriptor, 0, SEEK_END);
        return;
      }
      descriptor = ::open(filename.c_str(),
                          O_WRONLY | O_CREAT | O_TRUNC | O_NONBLOCK,
                          0644);
      if (descriptor < 0)
        throw OutputError(describe_system_error(errno, "creating", filename));
      write_row(format_row(columns));
    }


    void
    CsvFile::add_row(const std::vector<double> &values)
    {
      if (values.size() != columns.size())
        throw std::logic_error("wrong number of values for " + filename);
      if (descriptor < 0 && writes_files())
        throw std::logic_error("CsvFile::add_row before open: " + filename);
      check_row(values, columns, filename);
      if (writes_files())
        write_row(format_row(values));
    }


    void
    CsvFile::write_row(const std::string &row)
    {
      if (!write_all(descriptor, row.data(), row.size()))
      {
        const int error_number = errno;
        // Whatever part of the row reached the file is cut off again, so
        // that the file ends with a whole row (a special file such as
        // /dev/full cannot be truncated; it holds nothing anyway).
        if (::ftruncate(descriptor, size) == 0)
          ::lseek(descriptor, size, SEEK_SET);
        throw OutputError(
          describe_system_error(error_number, "writing", filename));
      }
      size += static_cast<long long>(row.size());
    }


    void
    CsvFile::close()
    {
      if (descriptor < 0)
        return;
      const int result = ::close(descriptor);
      descriptor       = -1;
      if (result != 0)
        throw OutputError(describe_system_error(errno, "closing", filename));
    }


    void
    CsvFile::close_silently()
    {
      if (descriptor >= 0)
        ::close(descriptor);
      descriptor = -1;
    }


    void
    write_csv_file_atomically(const std::string                      &filename,
                              const std::vector<std::string>         &columns,
                              const std::vector<std::vector<double>> &rows)
    {
      std::string content = format_row(columns);
      for (const std::vector<double> &row : rows)
      {
        if (row.size() != columns.size())
          throw std::logic_error("wrong number of values for " + filename);
        check_row(row, columns, filename);
        content += format_row(row);
      }
      write_file_atomically(filename, content);
    }
  } // namespace io
} // namespace deepdraw
