// The NUMISHEET'93 measures of the springback of a channel section (2D draw
// bending, doc/theory.md §9.4, D153): from the mid-surface of the section
// as points (s, z) in its plane, the angle theta1 between the bottom and
// the wall, theta2 between the wall and the flange, and the radius of
// curvature rho of the wall.
#ifndef deepdraw_postprocess_channel_measures_h
#define deepdraw_postprocess_channel_measures_h

#include <deal.II/base/point.h>
#include <vector>

namespace deepdraw
{
  namespace postprocess
  {
    using namespace dealii;

    struct ChannelMeasures
    {
      // Degrees: the angle inside the section between the fitted lines of
      // the parts, 180 - the angle between their directions of travel
      // along the section (90 for a channel with a vertical wall).
      double theta1 = 0.;
      double theta2 = 0.;
      // mm: the radius of the circle fitted to the wall (algebraic least
      // squares); infinite for a straight wall.
      double rho = 0.;
    };

    // bottom, wall, flange: the points of each part, in the order of the
    // section (at least 2, 3 and 2). Throws std::invalid_argument if a
    // part has too few points.
    ChannelMeasures
    channel_measures(const std::vector<Point<2>> &bottom,
                     const std::vector<Point<2>> &wall,
                     const std::vector<Point<2>> &flange);
  } // namespace postprocess
} // namespace deepdraw

#endif
