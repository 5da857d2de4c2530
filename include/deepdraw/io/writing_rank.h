// Under mpirun every rank runs the whole model and rank 0 alone writes the
// results (D199): the functions that make, write, truncate or lock files
// in the output directory do nothing where writes_files() is false.
#ifndef deepdraw_io_writing_rank_h
#define deepdraw_io_writing_rank_h

#include <string>

namespace deepdraw
{
  namespace io
  {
    bool
    writes_files();
    // main sets it once, after MPI has started.
    void
    set_writes_files(bool writes);

    // write_file_atomically on every rank: each rank's piece of a VTU
    // output (D201).
    void
    write_own_file_atomically(const std::string &filename,
                              const std::string &content);
  } // namespace io
} // namespace deepdraw

#endif
