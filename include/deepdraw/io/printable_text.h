// Text that is safe to print on a terminal in one line: messages quote
// lines of input files, which may hold control characters or the bytes of
// a binary file (doc/user_guide.md §5.2).
#ifndef deepdraw_io_printable_text_h
#define deepdraw_io_printable_text_h

#include <deal.II/base/exceptions.h>
#include <string>

namespace deepdraw
{
  namespace io
  {
    // Runs of whitespace (newlines included) become one space, the ends are
    // trimmed; bytes that are not printable ASCII or part of valid UTF-8
    // are shown as \xNN; longer texts are cut to max_length bytes with "...".
    std::string
    one_line(const std::string &text, std::size_t max_length = 2000);

    // A number in messages: 12 significant digits, the shortest form.
    std::string
    to_string(double value);

    // deal.II's exception text without its source-location preamble and
    // stack trace, as one_line().
    std::string
    deal_ii_message(const dealii::ExceptionBase &exception);

    // The first byte offset where text is not valid UTF-8 or holds a control
    // character other than tab, newline, carriage return and form feed;
    // std::string::npos if there is none.
    std::size_t
    find_non_text_byte(const std::string &text);
  } // namespace io
} // namespace deepdraw

#endif
