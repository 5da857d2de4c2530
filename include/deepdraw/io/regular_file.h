// Every path deepdraw reads or writes is checked to be a regular file (or,
// for an output, absent) before it is opened (doc/user_guide.md §5.2,
// D164): opening a named pipe blocks until another process opens its other
// end, and a device such as /dev/zero never ends. One stat(2), no open.
#ifndef deepdraw_io_regular_file_h
#define deepdraw_io_regular_file_h

#include <string>

namespace deepdraw
{
  namespace io
  {
    // Throws InputError unless path names a regular file (links followed):
    //   "<path>: cannot open the <kind> (No such file or directory)",
    //   "<path>: is a directory, not a <kind>",
    //   "<path>: is a named pipe, not a regular file (the <kind>)".
    // kind names the file in messages ("parameter file", "mesh file").
    void
    check_regular_file(const std::string &path, const std::string &kind);

    // Throws InputError "<path>: is a named pipe, not a regular file;
    // deepdraw would write its results there" if path is a named pipe, a
    // device or a socket (links followed): what blocks or never ends. A
    // directory in the way is left to the write, which fails naming it.
    void
    check_output_path(const std::string &path);

    // check_output_path for every entry of an existing directory that a run
    // writes or replaces: tables (.csv), ParaView files (.vtu, .pvd),
    // temporary files (.tmp), the checkpoint (.bin) and a study's plot
    // (.gp, .png).
    void
    check_output_entries(const std::string &directory);
  } // namespace io
} // namespace deepdraw

#endif
