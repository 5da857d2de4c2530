#include <cstdio>
#include <deepdraw/io/csv_file.h>
#include <iomanip>
#include <sstream>
#include <stdexcept>

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
        return row.str();
      }
    } // namespace


    CsvFile::CsvFile(const std::string              &filename,
                     const std::vector<std::string> &columns)
    {
      open(filename, columns);
    }


    void
    CsvFile::open(const std::string              &name,
                  const std::vector<std::string> &columns,
                  const bool                      append)
    {
      filename  = name;
      n_columns = columns.size();
      if (append)
      {
        std::ifstream existing(filename);
        std::string   header;
        if (!std::getline(existing, header) || header != format_row(columns))
          throw std::runtime_error(filename
                                   + " does not have the columns of this run");
        file.open(filename, std::ios::app);
      }
      else
        file.open(filename);
      if (!file)
        throw std::runtime_error("cannot write " + filename);
      if (!append)
        file << format_row(columns) << std::endl;
    }


    void
    CsvFile::add_row(const std::vector<double> &values)
    {
      if (values.size() != n_columns)
        throw std::logic_error("wrong number of values for " + filename);
      file << format_row(values) << std::endl;
    }


    void
    write_file_atomically(const std::string &filename,
                          const std::string &content)
    {
      const std::string temporary = filename + ".tmp";
      {
        std::ofstream out(temporary);
        out << content;
        if (!out)
          throw std::runtime_error("cannot write " + temporary);
      }
      if (std::rename(temporary.c_str(), filename.c_str()) != 0)
        throw std::runtime_error("cannot rename " + temporary + " to "
                                 + filename);
    }


    void
    write_csv_file_atomically(const std::string                      &filename,
                              const std::vector<std::string>         &columns,
                              const std::vector<std::vector<double>> &rows)
    {
      std::string content = format_row(columns) + "\n";
      for (const std::vector<double> &row : rows)
      {
        if (row.size() != columns.size())
          throw std::logic_error("wrong number of values for " + filename);
        content += format_row(row) + "\n";
      }
      write_file_atomically(filename, content);
    }
  } // namespace io
} // namespace deepdraw
