// Errors of muparser expressions (dealii::FunctionParser) as one line of
// deepdraw's own message: deal.II 9.4 prints muparser's diagnostic lines
// (Message, Formula, Token, Position, Errc) to std::cerr before it throws,
// both in FunctionParser::initialize and at the first evaluation, which
// put raw lines on the terminal ahead of the message naming the parameter
// (doc/user_guide.md §5.2).
#ifndef deepdraw_io_expression_error_h
#define deepdraw_io_expression_error_h

#include <functional>
#include <string>

namespace deepdraw
{
  namespace io
  {
    // Runs action (which initialises or evaluates a FunctionParser) with
    // std::cerr captured. Returns "" if it succeeded, otherwise the reason
    // in one line: muparser's message ("Unexpected end of expression at
    // position 6") or the exception's. Not thread safe (std::cerr is
    // global): for the parse phase, which runs on one thread.
    std::string
    expression_error(const std::function<void()> &action);
  } // namespace io
} // namespace deepdraw

#endif
