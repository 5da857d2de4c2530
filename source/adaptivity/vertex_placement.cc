#include <algorithm>
#include <cmath>
#include <deal.II/base/geometry_info.h>
#include <deepdraw/adaptivity/history_interpolation.h>
#include <deepdraw/adaptivity/vertex_placement.h>
#include <map>
#include <set>

namespace deepdraw
{
  namespace adaptivity
  {
    namespace
    {
      // A neighbour c of a continues the line b -> a beyond a if (c - a) is
      // within 25 degrees of (a - b) (cos < -0.9: the mesh lines of the
      // blank are straight; the polar disc's rings bend by less) and
      // |c - a| is 1/2 to 2 times |b - a| (a line of the same level).
      constexpr double continuation_cosine = -0.9;

      // The old vertex beyond a on the line b -> a, or -1: among the lines
      // at a, the one closest in length to (b, a) (a line of the same
      // level where there is one), skipping vertices that hang (they sit on
      // a chord, not on the surface).
      int
      continuation(const unsigned int                            a,
                   const unsigned int                            b,
                   const std::vector<Point<3>>                  &reference,
                   const std::vector<std::vector<unsigned int>> &neighbours,
                   const std::vector<bool>                      &excluded)
      {
        const Tensor<1, 3> edge        = reference[b] - reference[a];
        const double       length      = edge.norm();
        int                best        = -1;
        double             best_misfit = 0.;
        for (const unsigned int c : neighbours[a])
        {
          if (c == b || excluded[c])
            continue;
          const Tensor<1, 3> beyond = reference[c] - reference[a];
          const double       ratio  = beyond.norm() / length;
          if (ratio < 0.5 || ratio > 2.)
            continue;
          const double cosine = beyond * edge / (beyond.norm() * length);
          const double misfit = std::abs(std::log(ratio));
          if (cosine < continuation_cosine
              && (best < 0 || misfit < best_misfit))
          {
            best_misfit = misfit;
            best        = int(c);
          }
        }
        return best;
      }

      // Lagrange interpolation through (t_i, x_i) at t.
      Point<3>
      lagrange(const std::vector<double>   &t,
               const std::vector<Point<3>> &x,
               const double                 at)
      {
        Point<3> sum;
        for (unsigned int i = 0; i < t.size(); ++i)
        {
          double weight = 1.;
          for (unsigned int j = 0; j < t.size(); ++j)
            if (j != i)
              weight *= (at - t[j]) / (t[i] - t[j]);
          sum += weight * x[i];
        }
        return sum;
      }

      // Smooth position of the midpoint of edge (a, b) minus its chord
      // midpoint: the cubic (or quadratic at an end of the line) through
      // the old vertices of the line, with the arc length of the reference
      // configuration as parameter, at the reference midpoint.
      Tensor<1, 3>
      edge_correction(const unsigned int                            a,
                      const unsigned int                            b,
                      const std::vector<Point<3>>                  &current,
                      const std::vector<Point<3>>                  &reference,
                      const std::vector<std::vector<unsigned int>> &neighbours,
                      const std::vector<bool>                      &excluded)
      {
        const int before = continuation(a, b, reference, neighbours, excluded);
        const int after  = continuation(b, a, reference, neighbours, excluded);
        if (before < 0 && after < 0)
          return Tensor<1, 3>();
        const double          length = reference[a].distance(reference[b]);
        std::vector<double>   t      = {0., length};
        std::vector<Point<3>> x      = {current[a], current[b]};
        if (before >= 0)
        {
          t.push_back(-reference[a].distance(reference[before]));
          x.push_back(current[before]);
        }
        if (after >= 0)
        {
          t.push_back(length + reference[b].distance(reference[after]));
          x.push_back(current[after]);
        }
        Tensor<1, 3> correction
          = lagrange(t, x, 0.5 * length) - 0.5 * (current[a] + current[b]);
        // A straight line gives a correction of round-off size; dropping
        // it keeps deal.II's midpoint bit for bit on flat or affinely
        // deformed meshes (the sagitta of 1e-10 L is that of a radius of
        // 1e9 L).
        if (correction.norm() <= 1e-10 * length)
          correction = 0;
        return correction;
      }
    } // namespace


    std::vector<std::vector<unsigned int>>
    line_neighbours(const Triangulation<3> &mesh)
    {
      std::vector<std::set<unsigned int>> sets(mesh.n_vertices());
      for (const auto &cell : mesh.cell_iterators())
        for (const unsigned int l : cell->line_indices())
        {
          const auto line = cell->line(l);
          sets[line->vertex_index(0)].insert(line->vertex_index(1));
          sets[line->vertex_index(1)].insert(line->vertex_index(0));
        }
      std::vector<std::vector<unsigned int>> neighbours(mesh.n_vertices());
      for (unsigned int v = 0; v < sets.size(); ++v)
        neighbours[v].assign(sets[v].begin(), sets[v].end());
      return neighbours;
    }


    std::vector<bool>
    hanging_vertices(const Triangulation<3> &mesh)
    {
      std::vector<bool> hanging(mesh.n_vertices(), false);
      // Every vertex of a refined line of an active cell, but its ends.
      const auto mark_line = [&](const auto &line, const auto &self) -> void
      {
        if (!line->has_children())
          return;
        hanging[line->child(0)->vertex_index(1)] = true;
        for (unsigned int c = 0; c < line->n_children(); ++c)
          self(line->child(c), self);
      };
      // Every vertex of the children of a refined face of an active cell,
      // but the face's corners.
      const auto mark_face = [&](const auto &face, const auto &self) -> void
      {
        if (!face->has_children())
          return;
        for (unsigned int c = 0; c < face->n_children(); ++c)
        {
          const auto child = face->child(c);
          for (unsigned int l = 0; l < 4; ++l)
            mark_line(child->line(l), mark_line);
          for (unsigned int v = 0; v < 4; ++v)
          {
            bool corner = false;
            for (unsigned int w = 0; w < 4; ++w)
              corner
                = corner || child->vertex_index(v) == face->vertex_index(w);
            if (!corner)
              hanging[child->vertex_index(v)] = true;
          }
          self(child, self);
        }
      };
      for (const auto &cell : mesh.active_cell_iterators())
      {
        for (const unsigned int l : cell->line_indices())
          mark_line(cell->line(l), mark_line);
        for (const unsigned int f : cell->face_indices())
          mark_face(cell->face(f), mark_face);
      }
      return hanging;
    }


    std::vector<fe::VertexParents>
    hanging_edge_parents(const Triangulation<3> &mesh)
    {
      std::vector<fe::VertexParents> parents(mesh.n_vertices());
      for (const auto &cell : mesh.active_cell_iterators())
        for (const unsigned int l : cell->line_indices())
        {
          const auto line = cell->line(l);
          if (line->has_children())
            parents[line->child(0)->vertex_index(1)]
              = {{line->vertex_index(0), 0.5}, {line->vertex_index(1), 0.5}};
        }
      return parents;
    }


    std::vector<Point<3>>
    smooth_vertex_positions(
      const std::vector<Point<3>>                  &current,
      const std::vector<Point<3>>                  &reference,
      const std::vector<std::vector<unsigned int>> &neighbours,
      const std::vector<fe::VertexParents>         &parents,
      const std::vector<bool>                      &place,
      const std::vector<bool>                      &excluded)
    {
      // The midpoint of each refined edge: a face or cell centre takes the
      // correction of an edge only if its midpoint is placed too (not a
      // hanging one left on the chord), so that the children stay
      // consistent with the coarse neighbour at the edge of a refined zone.
      std::map<std::pair<unsigned int, unsigned int>, unsigned int> midpoint;
      for (unsigned int v = 0; v < current.size(); ++v)
        if (parents[v].size() == 2)
          midpoint[std::minmax(parents[v][0].first, parents[v][1].first)] = v;
      std::vector<Point<3>> positions = current;
      for (unsigned int v = 0; v < current.size(); ++v)
      {
        if (!place[v] || parents[v].size() < 2)
          continue;
        // Q1 position, plus the correction of every edge among the parents
        // (an edge midpoint: 1 edge; a face centre: 2 per direction, each
        // weighted 1/2; a cell centre: 4 per direction, 1/4). For a
        // surface x(s1, s2) this is exact for every quadratic in s1, s2:
        // the mixed term s1 s2 is bilinear, which Q1 already reproduces.
        const double weight = 2. / parents[v].size();
        Point<3>     x;
        for (const auto &[p, w] : parents[v])
          x += w * current[p];
        for (const auto &[a, wa] : parents[v])
          for (const auto &[b, wb] : parents[v])
            if (a < b
                && std::binary_search(neighbours[a].begin(),
                                      neighbours[a].end(),
                                      b)
                && (parents[v].size() == 2
                    || (midpoint.count({a, b}) > 0
                        && place[midpoint.at({a, b})])))
              x += weight
                   * edge_correction(a,
                                     b,
                                     current,
                                     reference,
                                     neighbours,
                                     excluded);
        // A coordinate all parents share exactly (a symmetry plane, D87)
        // stays exact.
        for (unsigned int d = 0; d < 3; ++d)
        {
          const double first = current[parents[v].front().first][d];
          bool         same  = true;
          for (const auto &[p, w] : parents[v])
            same = same && current[p][d] == first;
          if (same)
            x[d] = first;
        }
        positions[v] = x;
      }
      return positions;
    }


    Tensor<2, 3>
    placement_rotation(const std::array<Point<3>, 8> &from,
                       const std::array<Point<3>, 8> &to,
                       const Point<3>                &xi)
    {
      Tensor<2, 3> J_from, J_to;
      for (unsigned int v = 0; v < 8; ++v)
      {
        const Tensor<1, 3> gradient
          = GeometryInfo<3>::d_linear_shape_function_gradient(xi, v);
        J_from += outer_product(from[v], gradient);
        J_to += outer_product(to[v], gradient);
      }
      return nearest_rotation(J_to * invert(J_from));
    }
  } // namespace adaptivity
} // namespace deepdraw
