#include <algorithm>
#include <cmath>
#include <deepdraw/blank/sheet_thickness.h>

namespace deepdraw
{
  namespace blank
  {
    namespace
    {
      // Bilinear shape functions of a face in deal.II's vertex order.
      std::array<double, 4>
      shape_values(const double xi, const double eta)
      {
        return {
          {(1. - xi) * (1. - eta), xi * (1. - eta), (1. - xi) * eta, xi * eta}};
      }

      // Reference coordinates of X in the quadrilateral `corners` by
      // Newton's method; false if it does not converge.
      bool
      invert_bilinear(const std::array<Point<2>, 4> &c,
                      const Point<2>                &X,
                      double                        &xi,
                      double                        &eta)
      {
        xi = eta = 0.5;
        for (unsigned int iteration = 0; iteration < 20; ++iteration)
        {
          const std::array<double, 4> N = shape_values(xi, eta);
          Tensor<1, 2>                r = -X;
          for (unsigned int a = 0; a < 4; ++a)
            r += N[a] * c[a];
          const Tensor<1, 2> d_xi
            = (1. - eta) * (c[1] - c[0]) + eta * (c[3] - c[2]);
          const Tensor<1, 2> d_eta
            = (1. - xi) * (c[2] - c[0]) + xi * (c[3] - c[1]);
          const double det = d_xi[0] * d_eta[1] - d_xi[1] * d_eta[0];
          if (det == 0.)
            return false;
          const double dx = (r[0] * d_eta[1] - r[1] * d_eta[0]) / det;
          const double de = (d_xi[0] * r[1] - d_xi[1] * r[0]) / det;
          xi -= dx;
          eta -= de;
          if (std::abs(dx) + std::abs(de) < 1e-14)
            return true;
        }
        return false;
      }
    } // namespace


    SheetThickness::SheetThickness(
      const Triangulation<3>      &triangulation,
      const std::vector<Point<3>> &reference_vertices)
    {
      double extent = 0.;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary()
              && (face->boundary_id() == 4 || face->boundary_id() == 5))
          {
            add_face(face->boundary_id() == 4 ? bottom : top,
                     face,
                     cell,
                     reference_vertices);
            extent = std::max(extent, face->diameter());
          }
      // Points on an edge count for the faces on either side (1e-9 of the
      // largest face).
      tolerance = 1e-9 * extent;
      bottom.make_bins(tolerance);
      top.make_bins(tolerance);
      vertex_normal.resize(reference_vertices.size());
    }


    void
    SheetThickness::add_face(Surface                               &surface,
                             const Triangulation<3>::face_iterator &face,
                             const Triangulation<3>::active_cell_iterator &cell,
                             const std::vector<Point<3>> &reference_vertices)
    {
      std::array<unsigned int, 4> vertices;
      std::array<Point<2>, 4>     corners;
      Point<3>                    face_center, cell_center;
      for (unsigned int v = 0; v < 4; ++v)
      {
        vertices[v]       = face->vertex_index(v);
        const Point<3> &X = reference_vertices[vertices[v]];
        corners[v]        = Point<2>(X[0], X[1]);
        face_center += X / 4.;
      }
      for (const unsigned int v : cell->vertex_indices())
        cell_center += reference_vertices[cell->vertex_index(v)] / 8.;
      const auto  &X = reference_vertices;
      Tensor<1, 3> n = cross_product_3d(X[vertices[3]] - X[vertices[0]],
                                        X[vertices[2]] - X[vertices[1]]);
      surface.faces.push_back(vertices);
      surface.corners.push_back(corners);
      surface.orientation.push_back(n * (face_center - cell_center) < 0. ? -1.
                                                                         : 1.);
    }


    void
    SheetThickness::Surface::make_bins(const double tolerance)
    {
      if (faces.empty())
        return;
      Point<2> low = corners[0][0], high = corners[0][0];
      for (const auto &c : corners)
        for (const Point<2> &p : c)
          for (unsigned int d = 0; d < 2; ++d)
          {
            low[d]  = std::min(low[d], p[d]);
            high[d] = std::max(high[d], p[d]);
          }
      // About one face per bin.
      n_bins = std::max(1u, unsigned(std::ceil(std::sqrt(faces.size()))));
      origin = low;
      bin_size
        = std::max((high - low)[0], (high - low)[1]) / n_bins * (1. + 1e-12)
          + tolerance;
      bins.assign(n_bins * n_bins, {});
      const auto bin = [&](const double x)
      { return std::clamp<int>(std::floor(x / bin_size), 0, n_bins - 1); };
      for (unsigned int f = 0; f < faces.size(); ++f)
      {
        Point<2> a = corners[f][0], b = corners[f][0];
        for (const Point<2> &p : corners[f])
          for (unsigned int d = 0; d < 2; ++d)
          {
            a[d] = std::min(a[d], p[d]);
            b[d] = std::max(b[d], p[d]);
          }
        for (int j = bin(a[1] - origin[1] - tolerance);
             j <= bin(b[1] - origin[1] + tolerance);
             ++j)
          for (int i = bin(a[0] - origin[0] - tolerance);
               i <= bin(b[0] - origin[0] + tolerance);
               ++i)
            bins[i + j * n_bins].push_back(f);
      }
    }


    bool
    SheetThickness::Surface::find(const Point<2>              &X,
                                  const double                 tolerance,
                                  std::array<unsigned int, 4> &vertices,
                                  std::array<double, 4>       &weights) const
    {
      if (faces.empty())
        return false;
      const int i = std::floor((X[0] - origin[0]) / bin_size);
      const int j = std::floor((X[1] - origin[1]) / bin_size);
      if (i < 0 || j < 0 || i >= int(n_bins) || j >= int(n_bins))
        return false;
      for (const unsigned int f : bins[i + j * n_bins])
      {
        double xi, eta;
        if (!invert_bilinear(corners[f], X, xi, eta))
          continue;
        // Relative to the face: tolerance over its size.
        const double size = (corners[f][3] - corners[f][0]).norm()
                            + (corners[f][2] - corners[f][1]).norm();
        const double slack = 2. * tolerance / size;
        if (xi < -slack || xi > 1. + slack || eta < -slack || eta > 1. + slack)
          continue;
        // On a vertex or an edge within round-off: exactly there, so that a
        // point at a vertex takes that vertex's position (D72).
        const auto snap = [&](const double s) {
          return std::abs(s) <= slack ? 0. : std::abs(s - 1.) <= slack ? 1. : s;
        };
        vertices = faces[f];
        weights  = shape_values(snap(xi), snap(eta));
        return true;
      }
      return false;
    }


    std::optional<SheetThickness::Location>
    SheetThickness::locate(const Point<2> &X) const
    {
      Location location;
      if (bottom.find(X,
                      tolerance,
                      location.bottom_vertices,
                      location.bottom_weights)
          && top.find(X,
                      tolerance,
                      location.top_vertices,
                      location.top_weights))
        return location;
      return std::nullopt;
    }


    void
    SheetThickness::update(const std::vector<Point<3>> &vertices)
    {
      // The mean sheet normal at each surface vertex, from bottom to top:
      // the outward unit normals of the top faces there minus those of the
      // bottom faces (doc/theory.md §6).
      std::fill(vertex_normal.begin(), vertex_normal.end(), Tensor<1, 3>());
      for (const Surface *surface : {&bottom, &top})
      {
        const double sign = surface == &top ? 1. : -1.;
        for (unsigned int f = 0; f < surface->faces.size(); ++f)
        {
          const auto  &v = surface->faces[f];
          Tensor<1, 3> n = cross_product_3d(vertices[v[3]] - vertices[v[0]],
                                            vertices[v[2]] - vertices[v[1]]);
          n *= surface->orientation[f];
          n /= n.norm();
          for (const unsigned int vertex : v)
            vertex_normal[vertex] += sign * n;
        }
      }
    }


    double
    SheetThickness::thickness(const Location              &location,
                              const std::vector<Point<3>> &x) const
    {
      Tensor<1, 3> n, x_bottom, x_top;
      for (unsigned int a = 0; a < 4; ++a)
        if (location.bottom_weights[a] != 0.)
        {
          n += location.bottom_weights[a]
               * vertex_normal[location.bottom_vertices[a]];
          x_bottom
            += location.bottom_weights[a] * x[location.bottom_vertices[a]];
        }
      for (unsigned int a = 0; a < 4; ++a)
        if (location.top_weights[a] != 0.)
        {
          n += location.top_weights[a]
               * vertex_normal[location.top_vertices[a]];
          x_top += location.top_weights[a] * x[location.top_vertices[a]];
        }
      return std::abs((x_top - x_bottom) * n) / n.norm();
    }


    Point<3>
    SheetThickness::mid_surface(const Location              &location,
                                const std::vector<Point<3>> &x)
    {
      Tensor<1, 3> x_bottom, x_top;
      for (unsigned int a = 0; a < 4; ++a)
      {
        if (location.bottom_weights[a] != 0.)
          x_bottom
            += location.bottom_weights[a] * x[location.bottom_vertices[a]];
        if (location.top_weights[a] != 0.)
          x_top += location.top_weights[a] * x[location.top_vertices[a]];
      }
      return Point<3>(0.5 * (x_bottom + x_top));
    }


    std::vector<double>
    SheetThickness::ray_crossings(const Tensor<1, 2> &d) const
    {
      // Crossings with the edges of the bottom faces (an edge along the
      // ray crosses it at its ends, which the neighbouring edges give).
      std::vector<double> s = {0.};
      for (const auto &c : bottom.corners)
        for (const auto [a, b] : {std::pair{0, 1},
                                  std::pair{1, 3},
                                  std::pair{3, 2},
                                  std::pair{2, 0}})
        {
          const Tensor<1, 2> e     = c[b] - c[a];
          const double       denom = d[0] * e[1] - d[1] * e[0];
          if (std::abs(denom) <= 1e-14 * e.norm())
            continue;
          // s d = c[a] + t e.
          const double t     = (c[a][0] * d[1] - c[a][1] * d[0]) / denom;
          const double slack = tolerance / e.norm();
          if (t < -slack || t > 1. + slack)
            continue;
          const double along = (c[a][0] * e[1] - c[a][1] * e[0]) / denom;
          if (along >= -tolerance)
            s.push_back(std::max(0., along));
        }
      std::sort(s.begin(), s.end());
      s.erase(std::unique(s.begin(),
                          s.end(),
                          [&](const double a, const double b)
                          { return b - a <= tolerance; }),
              s.end());

      // From the first point on the sheet to the first gap.
      const auto on_sheet = [&](const double distance)
      { return locate(Point<2>(distance * d)).has_value(); };
      std::vector<double> inside;
      for (unsigned int i = 0; i < s.size(); ++i)
      {
        if (!on_sheet(s[i]))
        {
          if (inside.empty())
            continue;
          break;
        }
        if (!inside.empty() && !on_sheet(0.5 * (inside.back() + s[i])))
          break;
        inside.push_back(s[i]);
      }
      return inside;
    }
  } // namespace blank
} // namespace deepdraw
