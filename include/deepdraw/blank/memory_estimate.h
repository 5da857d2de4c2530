// How much memory a run needs, estimated from the size of its mesh before
// the mesh is made, and how much the machine has: a mesh too large for the
// memory is an input error naming both numbers (exit code 2,
// doc/user_guide.md §5.2, D53) instead of std::bad_alloc midway through
// the set-up.
#ifndef deepdraw_blank_memory_estimate_h
#define deepdraw_blank_memory_estimate_h

#include <deepdraw/blank/blank_geometry.h>

namespace deepdraw
{
  namespace blank
  {
    // The ranks of a run that share one machine's memory (D209). Every
    // rank holds the whole mesh; MUMPS splits its factors across all the
    // ranks of the run, UMFPACK factorises on every rank.
    struct RanksOnMachine
    {
      unsigned int on_this_machine = 1;
      unsigned int in_run          = 1;
      bool         factors_split   = false;
    };

    // Bytes a run with UMFPACK needs on one rank: the program, and per
    // cell and per contact pair (n_tools pairs per node of a sheet face)
    // what runs of the tension bar and the square cup measured, the
    // factors of the linear solver included (D53); per cell more with more
    // than 2 quadrature points through the thickness (D203). With several
    // ranks on the machine, what they need there together: each rank's
    // share of the model, and of the factors where they are split (D209).
    double
    estimated_memory(const BlankGeometry  &geometry,
                     unsigned int          n_tools,
                     unsigned int          points_through_thickness,
                     const RanksOnMachine &ranks = RanksOnMachine());

    // Bytes available to this process: MemAvailable of /proc/meminfo,
    // limited by the cgroup (memory.max - memory.current) where there is
    // one; infinity if neither can be read.
    double
    available_memory();

    // Throws InputError "the mesh of N cells needs about X GB, more than
    // the Y GB available" if estimated_memory > available_memory.
    void
    check_memory(const BlankGeometry  &geometry,
                 unsigned int          n_tools,
                 unsigned int          points_through_thickness,
                 const RanksOnMachine &ranks = RanksOnMachine());
  } // namespace blank
} // namespace deepdraw

#endif
