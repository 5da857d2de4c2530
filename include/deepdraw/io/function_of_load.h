// An expression of the load parameter t (and s, unused), with one or more
// components separated by ';', as the tool translations and forces are
// given: read and evaluated once at t = 0, so that a bad expression is an
// input error naming its parameter (D50).
#ifndef deepdraw_io_function_of_load_h
#define deepdraw_io_function_of_load_h

#include <deal.II/base/function_parser.h>
#include <memory>
#include <string>

namespace deepdraw
{
  namespace io
  {
    // Throws InputError: "<parameter> = '<text>': expected n expression(s)
    // of the load t separated by ';' (<muparser's reason>)".
    std::shared_ptr<dealii::FunctionParser<1>>
    parse_function_of_load(const std::string &text,
                           unsigned int       n_components,
                           const std::string &parameter);
  } // namespace io
} // namespace deepdraw

#endif
