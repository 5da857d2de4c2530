// Reading the parameter file into a dealii::ParameterHandler with the
// checks deal.II does not make (doc/user_guide.md §5.2, D52): before deal.II
// parses anything, the file and every file it includes are read as text
// files (io/text_file.h) and the `include` lines are followed the way
// deal.II follows them (paths relative to the current directory), so that
// a file that includes itself, two files that include each other, or
// includes nested deeper than max_include_depth are an InputError naming
// the chain instead of an endless recursion. A value with '{' (deal.II's
// syntax for several runs, which deepdraw does not have) is rejected too.
#ifndef deepdraw_io_parameter_file_h
#define deepdraw_io_parameter_file_h

#include <deal.II/base/parameter_handler.h>
#include <string>

namespace deepdraw
{
  namespace io
  {
    constexpr unsigned int max_include_depth = 16;

    // Throws InputError "FILE:LINE: ..." with the include chain, and turns
    // deal.II's own errors (unknown entry, value outside its pattern) into
    // InputError in one printable line. Files ending in .xml or .json are
    // handed to deal.II's readers of those formats (no includes there).
    void
    read_parameter_file(dealii::ParameterHandler &prm,
                        const std::string        &filename);
  } // namespace io
} // namespace deepdraw

#endif
