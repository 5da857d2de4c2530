// Adaptive refinement during the run (subsection Adaptivity,
// doc/user_guide.md §3.9, doc/theory.md §8.1, D80-D84): when to refine,
// which cells (the indicator) and how (isotropic, through the thickness or
// in the plane of the sheet). Off by default: a run without it is the run
// of a fixed mesh, bit for bit.
#ifndef deepdraw_adaptivity_adaptivity_parameters_h
#define deepdraw_adaptivity_adaptivity_parameters_h

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <string>

namespace deepdraw
{
  namespace adaptivity
  {
    using namespace dealii;

    struct AdaptivityParameters
    {
      bool enabled = false;
      // Refine after every this many converged increments.
      unsigned int interval = 5;
      // Refinement level a cell may reach (the blank's cells are level 0).
      unsigned int maximum_level = 2;
      // No refinement that would make more active cells than this.
      unsigned int maximum_cells = 100000;
      // "plastic strain jump", "tool curvature", "tool curvature or
      // plastic strain jump" (either selects) or "region"
      // (refinement_indicator.h).
      std::string indicator = "plastic strain jump";
      // Plastic strain jump: refine a cell whose cell-average equivalent
      // plastic strain differs from a face neighbour's by more than this.
      double jump_threshold = 0.02;
      // Tool curvature: refine a cell within one sheet thickness of a tool
      // whose in-plane size times the tool's curvature there exceeds this.
      double curvature_threshold = 0.25;
      // Region: refine the cells whose centre in the initial configuration
      // lies in the box [region_min, region_max] (mm).
      Point<3> region_min;
      Point<3> region_max;
      // "isotropic", "cut_z" (through the thickness) or "in_plane".
      std::string refinement = "isotropic";
      // "linear" or "smooth" (D87), "nearest" or "interpolated" (D88).
      std::string vertex_placement = "smooth";
      std::string history_transfer = "nearest";

      static void
      declare_parameters(ParameterHandler &prm);
      // Throws InputError naming the parameter.
      void
      parse_parameters(ParameterHandler &prm);

      // The deal.II refinement case of `refinement` (cell axes are the
      // blank's x, y, z: BlankGeometry's mesh).
      RefinementCase<3>
      refinement_case() const;
    };
  } // namespace adaptivity
} // namespace deepdraw

#endif
