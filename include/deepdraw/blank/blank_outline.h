// The in-plane outline of a non-rectangular blank (doc/user_guide.md §2.1):
// a circle of given diameter or a polygon read from an outline file, centred
// so that the origin lies inside. The blank mesh is a unit disc mesh mapped
// radially onto it (blank_mesh.h), so the outline must be star-shaped about
// the origin: every ray from the origin leaves it exactly once (D71).
#ifndef deepdraw_blank_blank_outline_h
#define deepdraw_blank_blank_outline_h

#include <cstddef>
#include <deal.II/base/point.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace blank
  {
    using namespace dealii;

    // Limits of an outline file (D169): its corners, and how far from the
    // origin they lie (mm; the upper one is BlankGeometry::max_extent).
    constexpr std::size_t max_outline_corners = 100000;
    constexpr double      max_outline_radius  = 1e4;
    constexpr double      min_outline_radius  = 1e-3;

    class BlankOutline
    {
    public:
      // An empty outline (radius 0 everywhere).
      BlankOutline() = default;

      // A circle of the given diameter about the origin.
      static BlankOutline
      circle(double diameter);

      // The polygon of an outline file: one "x y" per line (mm), '#' starts
      // a comment, blank lines are skipped, the last point joins the first
      // (a repeated first point at the end is dropped). Throws InputError
      // "FILE:LINE: ..." on a line that is not two finite numbers, more
      // than max_outline_corners or fewer than three points, two
      // consecutive equal points, a corner beyond max_outline_radius or all
      // within min_outline_radius, crossing edges, or an outline that is
      // not star-shaped about the origin.
      static BlankOutline
      read(const std::string &filename);

      // Distance from the origin to the outline along the direction at
      // angle theta (radians) from the x axis.
      double
      radius(double theta) const;

      // Largest distance of the outline from the origin.
      double
      max_radius() const;

      bool
      is_circle() const;

    private:
      double diameter = 0.;
      // Polygon corners, counterclockwise about the origin (empty: circle).
      std::vector<Point<2>> corners;
    };
  } // namespace blank
} // namespace deepdraw

#endif
