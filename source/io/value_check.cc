// Messages of unusable parameter values (doc/user_guide.md §5.2).
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/value_check.h>
#include <sstream>

namespace deepdraw
{
  namespace io
  {
    std::string
    number_text(const double value)
    {
      std::ostringstream s;
      s.precision(12);
      s << value;
      return s.str();
    }


    void
    require_value(const bool         condition,
                  const std::string &entry,
                  const double       value,
                  const std::string &allowed)
    {
      if (!condition)
        throw InputError("Invalid value " + number_text(value) + " of " + entry
                         + ": allowed values are " + allowed + ".");
    }
  } // namespace io
} // namespace deepdraw
