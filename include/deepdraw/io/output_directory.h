// Opening a run's output files as one step that either succeeds or leaves
// nothing behind (D11: an input error writes nothing).
#ifndef deepdraw_io_output_directory_h
#define deepdraw_io_output_directory_h

#include <functional>
#include <string>

namespace deepdraw
{
  namespace io
  {
    // Makes `directory` (with its parents) and calls open(), which creates
    // the files in it. If that fails, a directory made here (or, with
    // made_for_run, made for the run before) is removed again and an
    // InputError is thrown: open()'s own InputError unchanged, any other
    // failure as "parameter: cannot write results to ...".
    void
    open_output_directory(const std::string           &directory,
                          const std::string           &parameter,
                          const std::function<void()> &open,
                          bool                         made_for_run);

    // What open_output_directory() would refuse, found without making or
    // writing anything (--check): the directory, or the nearest ancestor
    // that exists, must be a directory the process may write in.
    void
    check_output_directory(const std::string &directory,
                           const std::string &parameter);

    // Whether name is a plain file name, one that stays in the directory
    // it is taken relative to: not empty, no '/', '\\' or NUL, not "." or
    // "..".
    bool
    is_plain_file_name(const std::string &name);
  } // namespace io
} // namespace deepdraw

#endif
