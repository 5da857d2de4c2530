// The one exception type for a result that cannot be written (disk full,
// permission lost, a non-finite value that must not reach a file). Every
// writer in io/ and the VTU writers throw it; main() prints its one-line
// message and exits with code 3 (doc/user_guide.md §5.1, D51). What was
// written before stays valid: CSV files end with a whole row, and files
// written through a temporary file keep their previous version.
#ifndef deepdraw_io_output_error_h
#define deepdraw_io_output_error_h

#include <stdexcept>
#include <string>

namespace deepdraw
{
  namespace io
  {
    class OutputError : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    // "<reason> while <doing> <filename>", the reason from errno in lower
    // case, e.g. "no space left on device while writing out/tools.csv".
    std::string
    describe_system_error(int                error_number,
                          const std::string &doing,
                          const std::string &filename);
  } // namespace io
} // namespace deepdraw

#endif
