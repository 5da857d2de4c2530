#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deepdraw/geometry/trimmed_domain.h>
#include <limits>

namespace deepdraw::geometry
{
  TrimmedDomain::TrimmedDomain(
    const std::vector<std::vector<dealii::Point<2>>> &loops,
    const double                                      tolerance)
      : loop_tolerance(tolerance)
  {
    for (const auto &loop : loops)
    {
      if (loop.size() < 3)
        continue;
      std::array<double, 4> box
        = {{loop[0][0], loop[0][0], loop[0][1], loop[0][1]}};
      for (const dealii::Point<2> &x : loop)
      {
        box[0] = std::min(box[0], x[0]);
        box[1] = std::max(box[1], x[0]);
        box[2] = std::min(box[2], x[1]);
        box[3] = std::max(box[3], x[1]);
      }
      loop_list.push_back(loop);
      loop_boxes.push_back(box);
    }
  }


  const std::vector<std::vector<dealii::Point<2>>> &
  TrimmedDomain::loops() const
  {
    return loop_list;
  }


  double
  TrimmedDomain::tolerance() const
  {
    return loop_tolerance;
  }


  bool
  TrimmedDomain::contains(const dealii::Point<2> &x) const
  {
    bool inside = false;
    for (unsigned int l = 0; l < loop_list.size(); ++l)
    {
      const std::array<double, 4> &box = loop_boxes[l];
      // A ray towards +U meets no edge of a loop beside or behind it.
      if (x[1] < box[2] || x[1] > box[3] || x[0] > box[1])
        continue;
      const auto        &loop = loop_list[l];
      const unsigned int n    = loop.size();
      for (unsigned int i = 0, j = n - 1; i < n; j = i++)
      {
        const dealii::Point<2> &a = loop[j], &b = loop[i];
        // Half-open in V, so that a vertex on the ray counts once.
        if ((a[1] > x[1]) != (b[1] > x[1]))
        {
          const double u_crossing
            = a[0] + (x[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
          if (x[0] < u_crossing)
            inside = !inside;
        }
      }
    }
    return inside;
  }


  namespace
  {
    // Distance from x to the segment [a, b] with the edge and the offset of
    // x mapped onto the tangent plane.
    double
    segment_distance(const dealii::Point<2>     &a,
                     const dealii::Point<2>     &b,
                     const dealii::Point<2>     &x,
                     const dealii::Tensor<1, 3> &x_U,
                     const dealii::Tensor<1, 3> &x_V)
    {
      const dealii::Tensor<1, 3> edge
        = (b[0] - a[0]) * x_U + (b[1] - a[1]) * x_V;
      const dealii::Tensor<1, 3> offset
        = (x[0] - a[0]) * x_U + (x[1] - a[1]) * x_V;
      const double length_square = edge.norm_square();
      const double lambda
        = length_square > 0.
            ? std::min(1., std::max(0., (offset * edge) / length_square))
            : 0.;
      return (offset - lambda * edge).norm();
    }
  } // namespace


  double
  TrimmedDomain::boundary_distance(const dealii::Point<2>     &x,
                                   const dealii::Tensor<1, 3> &x_U,
                                   const dealii::Tensor<1, 3> &x_V) const
  {
    double shortest = std::numeric_limits<double>::max();
    for (const auto &loop : loop_list)
    {
      const unsigned int n = loop.size();
      for (unsigned int i = 0, j = n - 1; i < n; j = i++)
        shortest
          = std::min(shortest, segment_distance(loop[j], loop[i], x, x_U, x_V));
    }
    return shortest;
  }


  double
  polyline_distance(const std::vector<dealii::Point<2>> &polyline,
                    const dealii::Point<2>              &x,
                    const dealii::Tensor<1, 3>          &x_U,
                    const dealii::Tensor<1, 3>          &x_V)
  {
    double shortest = std::numeric_limits<double>::max();
    for (unsigned int i = 1; i < polyline.size(); ++i)
      shortest
        = std::min(shortest,
                   segment_distance(polyline[i - 1], polyline[i], x, x_U, x_V));
    return shortest;
  }


  bool
  TrimmedDomain::crosses(const double u0,
                         const double u1,
                         const double v0,
                         const double v1) const
  {
    // Round-off of loop vertices on the rectangle's sides is not a crossing.
    const double margin_u = 1e-9 * (u1 - u0), margin_v = 1e-9 * (v1 - v0);
    const double lo[2] = {u0 + margin_u, v0 + margin_v};
    const double hi[2] = {u1 - margin_u, v1 - margin_v};
    for (const auto &loop : loop_list)
    {
      const unsigned int n = loop.size();
      for (unsigned int i = 0, j = n - 1; i < n; j = i++)
      {
        const dealii::Point<2> &a = loop[j], &b = loop[i];
        // Liang-Barsky: the part of a + lambda (b - a), lambda in [0, 1],
        // inside the rectangle.
        double enter = 0., leave = 1.;
        bool   empty = false;
        for (unsigned int d = 0; d < 2 && !empty; ++d)
        {
          const double delta = b[d] - a[d];
          if (delta == 0.)
            empty = a[d] <= lo[d] || a[d] >= hi[d];
          else
          {
            double t0 = (lo[d] - a[d]) / delta, t1 = (hi[d] - a[d]) / delta;
            if (t0 > t1)
              std::swap(t0, t1);
            enter = std::max(enter, t0);
            leave = std::min(leave, t1);
            empty = enter >= leave;
          }
        }
        if (!empty)
          return true;
      }
    }
    return false;
  }


  bool
  PatchTrimming::trimmed() const
  {
    return domain != nullptr;
  }


  bool
  PatchTrimming::contains(const double                s,
                          const double                t,
                          const dealii::Tensor<1, 3> &x_s,
                          const dealii::Tensor<1, 3> &x_t) const
  {
    if (!domain)
      return true;
    const dealii::Point<2> x(u0 + du * s, v0 + dv * t);
    if (domain->contains(x))
      return true;
    // dx/dU = x_s / du, dx/dV = x_t / dv.
    return domain->boundary_distance(x, x_s / du, x_t / dv)
           <= domain->tolerance();
  }
} // namespace deepdraw::geometry
