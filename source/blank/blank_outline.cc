#include <algorithm>
#include <cmath>
#include <deepdraw/blank/blank_outline.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/text_file.h>
#include <sstream>

namespace deepdraw
{
  namespace blank
  {
    namespace
    {
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

      struct NumberedPoint
      {
        Point<2>     point;
        unsigned int line;
      };

      std::vector<NumberedPoint>
      parse_points(const std::string &filename)
      {
        std::istringstream in(io::read_text_file(filename, "outline file"));
        std::vector<NumberedPoint> points;
        std::string                text;
        for (unsigned int line = 1; std::getline(in, text); ++line)
        {
          text = text.substr(0, text.find('#'));
          std::istringstream fields(text);
          double             x = 0., y = 0.;
          std::string        rest;
          if (text.find_first_not_of(" \t\r\f") == std::string::npos)
            continue;
          if (!(fields >> x >> y) || (fields >> rest) || !std::isfinite(x)
              || !std::isfinite(y))
            throw InputError(io::one_line(filename, 300) + ":"
                             + std::to_string(line)
                             + ": expected two numbers 'x y' (mm), got '"
                             + io::one_line(text, 200) + "'");
          points.push_back({Point<2>(x, y), line});
        }
        return points;
      }
    } // namespace


    BlankOutline
    BlankOutline::circle(const double diameter)
    {
      BlankOutline outline;
      outline.diameter = diameter;
      return outline;
    }


    BlankOutline
    BlankOutline::read(const std::string &filename)
    {
      std::vector<NumberedPoint> points = parse_points(filename);
      const auto fail = [&](const unsigned int line, const std::string &what)
      {
        throw InputError(io::one_line(filename, 300) + ":"
                         + std::to_string(line) + ": " + what);
      };
      if (points.size() > 3 && points.back().point == points.front().point)
        points.pop_back();
      if (points.size() < 3)
        fail(points.empty() ? 1 : points.back().line,
             "an outline needs at least three points, the file has "
               + std::to_string(points.size()));
      const std::size_t n = points.size();
      for (std::size_t i = 0; i < n; ++i)
        if (points[i].point == points[(i + 1) % n].point)
          fail(points[(i + 1) % n].line, "the point repeats the one before");

      // Crossing edges (the polygon must be simple); neighbours share a
      // corner and are not compared.
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j)
          if ((j + 1) % n != i
              && segments_intersect(points[i].point,
                                    points[(i + 1) % n].point,
                                    points[j].point,
                                    points[(j + 1) % n].point))
            fail(points[j].line,
                 "the edge from this point crosses the edge from line "
                   + std::to_string(points[i].line)
                   + " (the outline intersects itself)");

      // Star-shaped about the origin (D71): every edge turns the same way
      // about it and the edges go round it exactly once.
      double turning = 0.;
      double sign    = 0.;
      for (std::size_t i = 0; i < n; ++i)
      {
        const Point<2> &a = points[i].point, &b = points[(i + 1) % n].point;
        const double    c = cross(a, b);
        if (sign == 0.)
          sign = c > 0. ? 1. : -1.;
        if (!(c * sign > 0.))
          fail(points[(i + 1) % n].line,
               "the outline is not star-shaped about the origin: the ray "
               "from the origin through this point does not leave the "
               "outline once (the origin must lie inside, each direction "
               "must meet the outline once)");
        turning += std::atan2(c, a * b);
      }
      if (std::abs(std::abs(turning) - 2. * M_PI) > 1e-6)
        fail(points.back().line,
             "the outline does not go once round the origin");

      BlankOutline outline;
      for (const NumberedPoint &p : points)
        outline.corners.push_back(p.point);
      if (sign < 0.)
        std::reverse(outline.corners.begin(), outline.corners.end());
      return outline;
    }


    double
    BlankOutline::radius(const double theta) const
    {
      if (corners.empty())
        return 0.5 * diameter;
      // The edge the ray crosses: the corners are counterclockwise and every
      // edge turns positively about the origin, so the ray meets the edge
      // (a, b) with cross(a, d) >= 0 >= cross(b, d).
      const Tensor<1, 2> d({std::cos(theta), std::sin(theta)});
      const std::size_t  n = corners.size();
      for (std::size_t i = 0; i < n; ++i)
      {
        const Point<2> &a = corners[i], &b = corners[(i + 1) % n];
        if (cross(a, d) >= 0. && cross(b, d) <= 0.)
        {
          // a + s (b - a) = r d.
          const double   s = cross(a, d) / cross(a - b, d);
          const Point<2> x = a + s * (b - a);
          if (x * d > 0.)
            return x.norm();
        }
      }
      return 0.;
    }


    double
    BlankOutline::max_radius() const
    {
      if (corners.empty())
        return 0.5 * diameter;
      double r = 0.;
      for (const Point<2> &p : corners)
        r = std::max(r, p.norm());
      return r;
    }


    bool
    BlankOutline::is_circle() const
    {
      return corners.empty();
    }
  } // namespace blank
} // namespace deepdraw
