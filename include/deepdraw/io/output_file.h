// Checked low-level writes (POSIX file descriptors, so that every failed
// write is seen with its errno and no buffer hides it until a flush). All
// functions throw io::OutputError with a one-line reason naming the file.
#ifndef deepdraw_io_output_file_h
#define deepdraw_io_output_file_h

#include <cstddef>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace io
  {
    // write(2) until all size bytes are out (EINTR retried); false with
    // errno set otherwise.
    bool
    write_all(int descriptor, const char *data, std::size_t size);

    // Writes content to filename through filename.tmp and a rename, so that
    // the file on disk is always either the old or the new version; on any
    // failure the temporary file is removed.
    void
    write_file_atomically(const std::string &filename,
                          const std::string &content);

    // Throws OutputError unless every value is finite and representable as
    // a 32-bit float (VTU data arrays are written in single precision, where
    // values beyond 3.4e38 become inf). what names the field and file.
    void
    check_finite_for_output(const std::vector<double> &values,
                            const std::string         &what);
    void
    check_finite_for_output(const double      *begin,
                            const double      *end,
                            const std::string &what);
  } // namespace io
} // namespace deepdraw

#endif
