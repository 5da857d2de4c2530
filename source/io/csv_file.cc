#include <cstdio>
#include <deepdraw/io/csv_file.h>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace deepdraw
{
  namespace io
  {
    CsvFile::CsvFile(const std::string              &filename,
                     const std::vector<std::string> &columns)
    {
      open(filename, columns);
    }


    void
    CsvFile::open(const std::string              &name,
                  const std::vector<std::string> &columns)
    {
      filename  = name;
      n_columns = columns.size();
      file.open(filename);
      if (!file)
        throw std::runtime_error("cannot write " + filename);
      for (std::size_t c = 0; c < columns.size(); ++c)
        file << (c ? "," : "") << columns[c];
      file << std::endl;
    }


    void
    CsvFile::add_row(const std::vector<double> &values)
    {
      if (values.size() != n_columns)
        throw std::logic_error("wrong number of values for " + filename);
      std::ostringstream row;
      row << std::setprecision(10);
      for (std::size_t c = 0; c < values.size(); ++c)
        row << (c ? "," : "") << values[c];
      file << row.str() << std::endl;
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
  } // namespace io
} // namespace deepdraw
