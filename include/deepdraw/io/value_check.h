// The message of a parameter value that a deal.II Pattern accepts but the
// program cannot use (doc/user_guide.md §5.2): "Invalid value V of
// Subsection/Entry: allowed values are ...". Shared by the parameter
// structs; material_parameters.cc has its own copy from before.
#ifndef deepdraw_io_value_check_h
#define deepdraw_io_value_check_h

#include <string>

namespace deepdraw
{
  namespace io
  {
    // A number as messages show it: up to 12 significant digits, no
    // trailing zeros.
    std::string
    number_text(double value);

    // Throws InputError unless condition holds; write the condition so
    // that NaN fails it (a > 0, not !(a <= 0)).
    void
    require_value(bool               condition,
                  const std::string &entry,
                  double             value,
                  const std::string &allowed);
  } // namespace io
} // namespace deepdraw

#endif
