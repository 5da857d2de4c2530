#include <algorithm>
#include <cmath>
#include <deepdraw/blank/blank_outline.h>
#include <deepdraw/blank/outline_crossing.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/text_file.h>
#include <optional>
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
          if (points.size() > max_outline_corners)
            throw InputError(io::one_line(filename, 300) + ":"
                             + std::to_string(line) + ": more than the "
                             + std::to_string(max_outline_corners)
                             + " corners an outline may have");
        }
        return points;
      }

      using Fault = std::optional<std::pair<unsigned int, std::string>>;

      // Corners in millimetres (D169): within the 10 m of a blank, and not
      // so small that the cross products of the checks underflow.
      Fault
      scale_fault(const std::vector<NumberedPoint> &points)
      {
        // hypot: |p| of a corner at 1e200 mm without overflow.
        const auto distance = [](const NumberedPoint &p)
        { return std::hypot(p.point[0], p.point[1]); };
        const NumberedPoint *farthest = &points.front();
        for (const NumberedPoint &p : points)
          if (distance(p) > distance(*farthest))
            farthest = &p;
        const double       r = distance(*farthest);
        std::ostringstream text;
        text << r;
        if (r > max_outline_radius)
          return std::make_pair(farthest->line,
                                "this corner lies " + text.str()
                                  + " mm from the origin, more than the "
                                    "10000 mm a blank may extend (outline "
                                    "coordinates are millimetres)");
        if (r < min_outline_radius)
          return std::make_pair(farthest->line,
                                "the outline reaches only " + text.str()
                                  + " mm from the origin, less than the "
                                    "0.001 mm a blank must (outline "
                                    "coordinates are millimetres)");
        return {};
      }

      // Why the polygon is not star-shaped about the origin (the line of
      // the first edge that turns the wrong way, or the last line), if it
      // is not; sign is +1 for counterclockwise corners, -1 otherwise.
      Fault
      star_shaped_fault(const std::vector<NumberedPoint> &points, double &sign)
      {
        const std::size_t n       = points.size();
        double            turning = 0.;
        sign                      = 0.;
        for (std::size_t i = 0; i < n; ++i)
        {
          const Point<2> &a = points[i].point, &b = points[(i + 1) % n].point;
          const double    c = cross(a, b);
          if (sign == 0.)
            sign = c > 0. ? 1. : -1.;
          if (!(c * sign > 0.))
            return std::make_pair(
              points[(i + 1) % n].line,
              "the outline is not star-shaped about the origin: the ray "
              "from the origin through this point does not leave the "
              "outline once (the origin must lie inside, each direction "
              "must meet the outline once)");
          turning += std::atan2(c, a * b);
        }
        if (std::abs(std::abs(turning) - 2. * M_PI) > 1e-6)
          return std::make_pair(points.back().line,
                                "the outline does not go once round the "
                                "origin");
        return {};
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

      if (const auto fault = scale_fault(points))
        fail(fault->first, fault->second);

      // Star-shaped about the origin (D71): every edge turns the same way
      // about it and the edges go round it exactly once. Such a polygon is
      // simple (an edge covers its own sector of directions), so crossing
      // edges are looked for only to name them when it is not (D169).
      double     sign  = 0.;
      const auto fault = star_shaped_fault(points, sign);
      if (fault)
      {
        std::vector<Point<2>> corners;
        for (const NumberedPoint &p : points)
          corners.push_back(p.point);
        if (const auto crossing = first_crossing(corners))
          fail(points[crossing->second].line,
               "the edge from this point crosses the edge from line "
                 + std::to_string(points[crossing->first].line)
                 + " (the outline intersects itself)");
        fail(fault->first, fault->second);
      }

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
