#include <cstdio>
#include <deepdraw/blank/memory_estimate.h>
#include <deepdraw/io/input_error.h>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

namespace deepdraw
{
  namespace blank
  {
    namespace
    {
      // Measured (D53): peak resident memory of runs of one increment with
      // UMFPACK, 2 layers, 12 x 12 to 100 x 100 cells in the plane: the
      // program itself, per cell (mesh, dofs, history, matrix and factors;
      // tension bar without tools) and per contact pair (square cup).
      constexpr double bytes_of_program = 170e6;
      constexpr double bytes_per_cell   = 48e3;
      constexpr double bytes_per_pair   = 19e3;
      // Per cell and point through the thickness beyond 2 (D202: 4 more
      // quadrature points' history and geometry, 3 more enhanced
      // parameters): the square cup's peak memory on 50 x 50 x 2 and
      // 100 x 100 x 2 grew by 2.84-2.96 kB a cell and point (D203).
      constexpr double bytes_per_cell_and_extra_point = 2.9e3;
      // The part of a one-rank run's memory that is MUMPS' factors, which
      // the ranks split: the 100 x 100 x 2 square cup on 1 and 2 ranks
      // (1 303 against 1 078 MB each, 1 458 against 1 221 MB with reused
      // factors) gives 0.345 and 0.325 (D209).
      constexpr double factor_fraction = 1. / 3.;

      // A number from a file such as /sys/fs/cgroup/memory.max; negative
      // if it cannot be read or says "max".
      double
      read_number(const std::string &filename)
      {
        std::ifstream in(filename);
        std::string   word;
        if (!(in >> word) || word == "max")
          return -1.;
        try
        {
          return std::stod(word);
        }
        catch (const std::exception &)
        {
          return -1.;
        }
      }
    } // namespace


    double
    estimated_memory(const BlankGeometry  &geometry,
                     const unsigned int    n_tools,
                     const unsigned int    points_through_thickness,
                     const RanksOnMachine &ranks)
    {
      const double nodes_per_face = geometry.n_plane_vertices();
      const double extra_points
        = points_through_thickness > 2 ? points_through_thickness - 2. : 0.;
      const double one_rank
        = bytes_of_program
          + (bytes_per_cell + bytes_per_cell_and_extra_point * extra_points)
              * geometry.n_cells()
          + bytes_per_pair * n_tools * nodes_per_face;
      // Each rank on the machine holds the model; the factors are split
      // over all ranks of the run, or held by each (UMFPACK).
      const double split = ranks.factors_split ? factor_fraction : 0.;
      const double k     = ranks.on_this_machine;
      return one_rank * (k * (1. - split) + split * k / ranks.in_run);
    }


    double
    available_memory()
    {
      double        available = std::numeric_limits<double>::infinity();
      std::ifstream meminfo("/proc/meminfo");
      std::string   key;
      double        kilobytes = 0.;
      std::string   unit;
      while (meminfo >> key >> kilobytes >> unit)
        if (key == "MemAvailable:")
          available = kilobytes * 1024.;
      const double limit   = read_number("/sys/fs/cgroup/memory.max");
      const double current = read_number("/sys/fs/cgroup/memory.current");
      if (limit >= 0. && current >= 0. && limit - current < available)
        available = std::max(0., limit - current);
      return available;
    }


    void
    check_memory(const BlankGeometry  &geometry,
                 const unsigned int    n_tools,
                 const unsigned int    points_through_thickness,
                 const RanksOnMachine &ranks)
    {
      const double needed
        = estimated_memory(geometry, n_tools, points_through_thickness, ranks);
      const double available = available_memory();
      if (needed <= available)
        return;
      std::ostringstream text;
      text << std::setprecision(3) << "Geometry: the mesh of ";
      if (geometry.outline == BlankGeometry::Outline::rectangle)
        text << geometry.elements_along_x << " x " << geometry.elements_along_y
             << " x ";
      else
        text << geometry.n_plane_cells() << " x ";
      text << geometry.layers_through_thickness << " = " << geometry.n_cells()
           << " cells";
      if (n_tools > 0)
        text << " with " << n_tools << " tool(s)";
      if (points_through_thickness > 2)
        text << " and " << points_through_thickness
             << " points through the thickness";
      text << " needs about " << needed / 1e9 << " GB of memory";
      if (ranks.on_this_machine > 1)
        text << " on this machine for its " << ranks.on_this_machine
             << " MPI ranks (estimated from measured runs; every rank holds "
                "the whole mesh)";
      else
        text << " (estimated from measured runs)";
      text << ", more than the " << available / 1e9 << " GB available; use "
           << (ranks.on_this_machine > 1 ? "fewer ranks on this machine, " : "")
           << "fewer Elements along x, Elements along y or Layers through "
              "thickness"
           << (points_through_thickness > 2
                 ? ", or Finite element/Points through the thickness"
                 : "");
      throw InputError(text.str());
    }
  } // namespace blank
} // namespace deepdraw
