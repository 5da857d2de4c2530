// The one exception type for unusable user input (prm values, tool files,
// command line). Its message names the parameter or the file and line, and
// the allowed values; main() prints it and exits non-zero before any output
// is written.
#ifndef deepdraw_io_input_error_h
#define deepdraw_io_input_error_h

#include <stdexcept>
#include <string>

namespace deepdraw
{
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace deepdraw

#endif
