// The NUMISHEET'93 measures of a channel section (postprocess::
// channel_measures, D153, doc/theory.md §9.4) on sections drawn by hand:
// - an ideal channel (flat bottom, vertical wall, flat flange): theta1 =
//   theta2 = 90 degrees;
// - its wall leaning out by 7 degrees and its flange rising by 3 degrees:
//   theta1 = 97, theta2 = 100;
// - a wall that is an arc of radius 150 mm over 20 degrees: rho = 150.
// The fits are exact on exact points: asserted to 1e-9 (degrees, mm
// relative).
#include "test_utilities.h"

#include <cmath>
#include <deepdraw/postprocess/channel_measures.h>

using namespace dealii;
using namespace deepdraw;

namespace
{
  const double degree = M_PI / 180.;

  // n + 1 points from a in direction angle (from the s axis), length l.
  std::vector<Point<2>>
  line(const Point<2> &a, const double angle, const double l, unsigned int n)
  {
    std::vector<Point<2>> points;
    for (unsigned int k = 0; k <= n; ++k)
      points.emplace_back(a[0] + l * k / n * std::cos(angle),
                          a[1] + l * k / n * std::sin(angle));
    return points;
  }
} // namespace

int
main()
{
  // Ideal: the bottom along +s at z = 0, the wall up, the flange along +s.
  {
    const auto bottom = line(Point<2>(0, 0), 0., 20., 10);
    const auto wall   = line(Point<2>(25, 5), 90. * degree, 50., 10);
    const auto flange = line(Point<2>(30, 60), 0., 40., 10);
    const postprocess::ChannelMeasures m
      = postprocess::channel_measures(bottom, wall, flange);
    deepdraw_test::check_close("ideal channel: theta1", m.theta1, 90., 1e-9);
    deepdraw_test::check_close("ideal channel: theta2", m.theta2, 90., 1e-9);
    deepdraw_test::check_true("ideal channel: straight wall, rho > 1e6 mm",
                              m.rho > 1e6);
  }
  // Sprung back: the wall leans out by 7 degrees (its direction of travel
  // at 83 degrees), the flange rises by 3 degrees (at 3 degrees): theta1 =
  // 180 - 83 = 97, theta2 = 180 - (83 - 3) = 100.
  {
    const auto bottom = line(Point<2>(0, 0), 0., 20., 10);
    const auto wall   = line(Point<2>(25, 5), 83. * degree, 50., 10);
    const auto flange = line(Point<2>(35, 60), 3. * degree, 40., 10);
    const postprocess::ChannelMeasures m
      = postprocess::channel_measures(bottom, wall, flange);
    deepdraw_test::check_close("sprung back: theta1", m.theta1, 97., 1e-9);
    deepdraw_test::check_close("sprung back: theta2", m.theta2, 100., 1e-9);
  }
  // A curled wall: an arc of radius 150 mm, centre (175, 40), from 160 to
  // 180 degrees.
  {
    std::vector<Point<2>> wall;
    for (unsigned int k = 0; k <= 20; ++k)
    {
      const double phi = (160. + k) * degree;
      wall.emplace_back(175. + 150. * std::cos(phi),
                        40. + 150. * std::sin(phi));
    }
    const auto bottom = line(Point<2>(-20, -20), 0., 10., 5);
    const auto flange = line(Point<2>(30, 60), 0., 40., 10);
    const postprocess::ChannelMeasures m
      = postprocess::channel_measures(bottom, wall, flange);
    deepdraw_test::check_close("curled wall: rho", m.rho, 150., 1e-9);
  }
  return deepdraw_test::summary();
}
