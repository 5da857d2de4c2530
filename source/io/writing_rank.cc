#include <deepdraw/io/writing_rank.h>

namespace deepdraw
{
  namespace io
  {
    namespace
    {
      bool this_process_writes = true;
    } // namespace


    bool
    writes_files()
    {
      return this_process_writes;
    }


    void
    set_writes_files(const bool writes)
    {
      this_process_writes = writes;
    }
  } // namespace io
} // namespace deepdraw
