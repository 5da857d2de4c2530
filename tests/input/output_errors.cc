// Failed writes (doc/user_guide.md §5.1, D51): every writer of io/ throws
// io::OutputError with a one-line reason naming the file; a CSV file keeps
// whole rows only; a file written atomically keeps its old version and no
// temporary file; no NaN or inf is written. A full disk is /dev/full; a
// file that fills up in the middle of a row is made with a file size limit
// (RLIMIT_FSIZE, SIGXFSZ ignored as deepdraw's main() does).
#include "../test_utilities.h"

#include <algorithm>
#include <csignal>
#include <deepdraw/io/csv_file.h>
#include <deepdraw/io/output_error.h>
#include <deepdraw/io/output_file.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/pvd_record.h>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <unistd.h>

using deepdraw_test::check_true;
namespace fs = std::filesystem;

namespace
{
  // The message of the OutputError that action throws, or "" if none.
  template <typename Action>
  std::string
  output_error(Action &&action)
  {
    try
    {
      action();
    }
    catch (const deepdraw::io::OutputError &error)
    {
      return error.what();
    }
    return "";
  }

  bool
  contains(const std::string &text, const std::string &part)
  {
    return text.find(part) != std::string::npos;
  }

  std::string
  read(const fs::path &path)
  {
    std::ifstream     in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  // Limits the size of files this process writes (soft limit only, so that
  // it can be lifted again).
  void
  limit_file_size(const rlim_t bytes)
  {
    rlimit limit;
    getrlimit(RLIMIT_FSIZE, &limit);
    limit.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limit);
  }
} // namespace


int
main()
{
  std::signal(SIGXFSZ, SIG_IGN);
  const fs::path directory
    = fs::temp_directory_path()
      / ("deepdraw_output_errors_" + std::to_string(::getpid()));
  fs::create_directories(directory);

  // A full disk: the message is one line with the reason and the file.
  {
    deepdraw::io::CsvFile file;
    const std::string     message = output_error(
      [&]() {
        file.open("/dev/full", {"a", "b"});
      });
    std::cout << "  /dev/full: " << message << std::endl;
    check_true("CsvFile on /dev/full: 'no space left on device while writing "
               "/dev/full'",
               message == "no space left on device while writing /dev/full");
    check_true("write_file_atomically into a directory that does not exist",
               contains(output_error(
                          [&]()
                          {
                            deepdraw::io::write_file_atomically(
                              (directory / "no/such/file").string(),
                              "x");
                          }),
                        "no such file or directory while creating"));
  }

  // A file that fills up in the middle of a row keeps whole rows only.
  {
    const fs::path        path = directory / "table.csv";
    deepdraw::io::CsvFile file(path.string(), {"load", "force", "travel"});
    limit_file_size(1000);
    std::string message;
    unsigned    rows = 0;
    while (message.empty() && rows < 1000)
    {
      message = output_error(
        [&]() {
          file.add_row({0.1 * rows, 12345.678901 * rows, -rows / 7.});
        });
      rows += message.empty();
    }
    limit_file_size(RLIM_INFINITY);
    std::cout << "  after " << rows << " rows: " << message << std::endl;
    check_true("the failed row is reported naming the file",
               contains(message,
                        "file too large while writing " + path.string()));
    const std::string  text  = read(path);
    unsigned           lines = 0, bad = 0;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line); ++lines)
      bad += std::count(line.begin(), line.end(), ',') != 2;
    check_true("the file ends with a whole row",
               !text.empty() && text.back() == '\n');
    check_true("every line has three values", bad == 0);
    check_true("every reported row is in the file", lines == rows + 1);
    // Writing on after the error appends to the last whole row.
    file.add_row({1., 2., 3.});
    check_true("a later row follows the last whole one",
               read(path).size() == text.size() + 6);
  }

  // A file written atomically keeps its old version and no .tmp file.
  {
    const fs::path path = directory / "solution.pvd";
    deepdraw::io::write_file_atomically(path.string(), "old version\n");
    limit_file_size(100);
    const std::string message = output_error(
      [&]()
      {
        deepdraw::io::write_file_atomically(path.string(),
                                            std::string(5000, 'x'));
      });
    limit_file_size(RLIM_INFINITY);
    std::cout << "  atomic write: " << message << std::endl;
    check_true("the failed write names the file",
               contains(message,
                        "file too large while writing " + path.string()));
    check_true("the old version stays", read(path) == "old version\n");
    check_true("no temporary file stays", !fs::exists(path.string() + ".tmp"));
  }

  // No NaN or inf is written: the value names its column, nothing of the
  // row is written.
  {
    const fs::path        path = directory / "tools.csv";
    deepdraw::io::CsvFile file(path.string(), {"load", "punch_uz"});
    const std::string     message = output_error(
      [&]() {
        file.add_row({0., -std::numeric_limits<double>::infinity()});
      });
    std::cout << "  non-finite: " << message << std::endl;
    check_true("a non-finite value names its column",
               contains(message,
                        "(-inf) in column punch_uz of " + path.string()));
    check_true("nothing of that row is written",
               read(path) == "load,punch_uz\n");
    check_true("a value beyond single precision is refused for VTU data",
               contains(output_error(
                          [&]()
                          {
                            const double value = 1e39;
                            deepdraw::io::check_finite_for_output(
                              &value,
                              &value + 1,
                              "a VTU field");
                          }),
                        "in a VTU field"));
    deepdraw::io::PvdRecord pvd((directory / "s.pvd").string());
    check_true("a pvd step at a non-finite time is refused",
               !output_error(
                  [&]()
                  {
                    pvd.add_step(std::numeric_limits<double>::quiet_NaN(),
                                 {"solution-00000.vtu"});
                  })
                  .empty());
  }

  // Messages are one printable line whatever they quote.
  check_true("one_line escapes control characters and invalid UTF-8",
             deepdraw::io::one_line("a\x1b[2J\nb \xff ≥")
               == "a\\x1B[2J b \\xFF ≥");

  fs::remove_all(directory);
  return deepdraw_test::summary();
}
