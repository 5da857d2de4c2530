#include <algorithm>
#include <cmath>
#include <deepdraw/blank/outline_crossing.h>
#include <numeric>

namespace deepdraw
{
  namespace blank
  {
    namespace
    {
      using dealii::Point;
      using dealii::Tensor;

      double
      cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
      {
        return a[0] * b[1] - a[1] * b[0];
      }

      // Whether the closed segments [a, b] and [c, d] share a point.
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
        // Touching or collinear overlap: a point of one segment on the other.
        const auto on_segment
          = [](const Point<2> &p, const Point<2> &q, const Point<2> &x)
        {
          return std::abs(cross(q - p, x - p)) <= 1e-12 * (q - p).norm_square()
                 && (x - p) * (q - p) >= 0. && (x - q) * (p - q) >= 0.;
        };
        return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a)
               || on_segment(c, d, b);
      }

      struct Box
      {
        double x_min, x_max, y_min, y_max;
      };
    } // namespace


    std::optional<std::pair<std::size_t, std::size_t>>
    first_crossing(const std::vector<Point<2>> &corners)
    {
      const std::size_t n = corners.size();
      std::vector<Box>  boxes(n);
      for (std::size_t k = 0; k < n; ++k)
      {
        // Widened by the tolerance of segments_intersect (a point within
        // 1e-12 of the edge's length touches it).
        const Point<2> &a = corners[k], &b = corners[(k + 1) % n];
        const double    margin
          = 1e-12 * (std::abs(b[0] - a[0]) + std::abs(b[1] - a[1]));
        boxes[k] = {std::min(a[0], b[0]) - margin,
                    std::max(a[0], b[0]) + margin,
                    std::min(a[1], b[1]) - margin,
                    std::max(a[1], b[1]) + margin};
      }
      std::vector<std::size_t> order(n);
      std::iota(order.begin(), order.end(), std::size_t(0));
      std::sort(order.begin(),
                order.end(),
                [&](const std::size_t p, const std::size_t q)
                { return boxes[p].x_min < boxes[q].x_min; });

      std::optional<std::pair<std::size_t, std::size_t>> first;
      std::vector<std::size_t> active; // edges whose x-range may reach on
      std::size_t              budget = max_crossing_comparisons * n;
      for (const std::size_t e : order)
      {
        const Box &box = boxes[e];
        // Edges ending left of this one end left of all that follow.
        active.erase(std::remove_if(active.begin(),
                                    active.end(),
                                    [&](const std::size_t a)
                                    { return boxes[a].x_max < box.x_min; }),
                     active.end());
        for (const std::size_t a : active)
        {
          if (budget-- == 0)
            return first;
          const std::size_t i = std::min(a, e), j = std::max(a, e);
          // Neighbours share a corner and are not compared.
          if (j == i + 1 || (i == 0 && j == n - 1))
            continue;
          if (boxes[a].y_max < box.y_min || box.y_max < boxes[a].y_min)
            continue;
          if (first && std::make_pair(i, j) >= *first)
            continue;
          if (segments_intersect(corners[i],
                                 corners[(i + 1) % n],
                                 corners[j],
                                 corners[(j + 1) % n]))
            first = std::make_pair(i, j);
        }
        active.push_back(e);
      }
      return first;
    }
  } // namespace blank
} // namespace deepdraw
