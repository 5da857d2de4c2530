#include <cctype>
#include <cstring>
#include <deepdraw/io/output_error.h>

namespace deepdraw
{
  namespace io
  {
    std::string
    describe_system_error(const int          error_number,
                          const std::string &doing,
                          const std::string &filename)
    {
      std::string reason = std::strerror(error_number);
      if (!reason.empty())
        reason[0] = std::tolower(static_cast<unsigned char>(reason[0]));
      return reason + " while " + doing + " " + filename;
    }
  } // namespace io
} // namespace deepdraw
