// Reading a whole input file as text, with the checks every input file
// gets before it is parsed (doc/user_guide.md §5.2): it must be a regular
// file (not a directory, device or pipe), readable, at most
// max_text_file_size bytes, and text (UTF-8 without control characters
// other than tab, newline, carriage return and form feed), so that a
// binary file is rejected without its bytes reaching the terminal. A
// leading UTF-8 byte-order mark is dropped (D175).
#ifndef deepdraw_io_text_file_h
#define deepdraw_io_text_file_h

#include <cstddef>
#include <string>

namespace deepdraw
{
  namespace io
  {
    constexpr std::size_t max_text_file_size = 16u << 20;

    // kind names the file in messages ("parameter file", "tool file"); the
    // errors are InputError "FILE: <what is wrong>" (with the line of the
    // first byte that is not text).
    std::string
    read_text_file(const std::string &filename, const std::string &kind);
  } // namespace io
} // namespace deepdraw

#endif
