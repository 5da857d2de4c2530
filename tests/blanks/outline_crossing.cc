// blank::first_crossing (D169) against the double loop it replaced: for
// random polygons of 4 to 40 corners (on a coarse grid, so that touching
// corners and collinear overlaps occur), with and without crossings, the
// same answer, the lowest pair (i, j) of non-neighbouring edges that share a
// point (polygons with a repeated point skipped, as the outline reader
// refuses them first); and a star-shaped polygon of 100 000 corners has none.
#include "test_utilities.h"

#include <cmath>
#include <deepdraw/blank/outline_crossing.h>
#include <optional>
#include <random>
#include <utility>
#include <vector>

using namespace dealii;
using namespace deepdraw::blank;
using namespace deepdraw_test;

namespace
{
  double
  cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
  {
    return a[0] * b[1] - a[1] * b[0];
  }

  // The test of blank_outline.cc before D169, verbatim.
  bool
  segments_intersect(const Point<2> &a,
                     const Point<2> &b,
                     const Point<2> &c,
                     const Point<2> &d)
  {
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
    const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    if (((d1 > 0. && d2 < 0.) || (d1 < 0. && d2 > 0.))
        && ((d3 > 0. && d4 < 0.) || (d3 < 0. && d4 > 0.)))
      return true;
    const auto on_segment
      = [](const Point<2> &p, const Point<2> &q, const Point<2> &x)
    {
      return std::abs(cross(q - p, x - p)) <= 1e-12 * (q - p).norm_square()
             && (x - p) * (q - p) >= 0. && (x - q) * (p - q) >= 0.;
    };
    return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a)
           || on_segment(c, d, b);
  }

  std::optional<std::pair<std::size_t, std::size_t>>
  double_loop(const std::vector<Point<2>> &p)
  {
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 2; j < n; ++j)
        if ((j + 1) % n != i
            && segments_intersect(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]))
          return std::make_pair(i, j);
    return std::nullopt;
  }
} // namespace


int
main()
{
  std::mt19937                       random(32);
  std::uniform_int_distribution<int> coordinate(-6, 6);
  unsigned int                       n_same = 0, n_crossing = 0, n_polygons = 0;
  for (unsigned int n = 4; n <= 40; ++n)
    for (unsigned int sample = 0; sample < 200; ++sample)
    {
      std::vector<Point<2>> corners;
      // Random walks and random star polygons, both on a 13 x 13 grid.
      for (unsigned int k = 0; k < n; ++k)
        if (sample % 2 == 0)
          corners.emplace_back(coordinate(random), coordinate(random));
        else
        {
          const double angle = 2. * M_PI * k / n;
          const double r     = 3 + (coordinate(random) + 6) / 4;
          corners.emplace_back(std::round(r * std::cos(angle)),
                               std::round(r * std::sin(angle)));
        }
      // As BlankOutline::read: no edge of zero length (a repeated point is
      // refused before the crossing search).
      bool repeated = false;
      for (unsigned int k = 0; k < n; ++k)
        repeated = repeated || corners[k] == corners[(k + 1) % n];
      if (repeated)
        continue;
      const auto expected = double_loop(corners);
      const auto found    = first_crossing(corners);
      ++n_polygons;
      n_crossing += expected.has_value();
      n_same += expected == found;
      if (expected != found)
        check_true("polygon " + std::to_string(n_polygons) + " of "
                     + std::to_string(n) + " corners: the same pair",
                   false);
    }
  check_true("the same answer for all " + std::to_string(n_polygons)
               + " polygons (" + std::to_string(n_crossing)
               + " with a crossing)",
             n_same == n_polygons && n_crossing > 0 && n_crossing < n_polygons);

  std::vector<Point<2>> circle;
  for (unsigned int k = 0; k < 100000; ++k)
    circle.emplace_back(50. * std::cos(2e-5 * M_PI * k),
                        50. * std::sin(2e-5 * M_PI * k));
  check_true("a circle of 100000 corners does not cross itself",
             !first_crossing(circle).has_value());
  return summary();
}
