// The surface strains of the sheet's columns (doc/theory_formability.md
// §1.1, D140).
#include <algorithm>
#include <cmath>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/value_check.h>
#include <deepdraw/postprocess/column_strains.h>
#include <optional>
#include <utility>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      using Cell      = Triangulation<3>::active_cell_iterator;
      using Footprint = std::array<std::pair<double, double>, 4>;

      // The neighbour across the through-thickness face f (4 below, 5
      // above) if it is an active cell with the same footprint: the two
      // share the whole face (not a coarser or a refined neighbour).
      std::optional<Cell>
      stacked_neighbour(const Cell &cell, const unsigned int f)
      {
        if (cell->at_boundary(f) || cell->face(f)->has_children())
          return std::nullopt;
        const auto neighbour = cell->neighbor(f);
        if (!neighbour->is_active()
            || neighbour->face_index(f ^ 1u) != cell->face_index(f))
          return std::nullopt;
        return Cell(neighbour);
      }

      // The in-plane corners (X, Y) at t = 0 of a cell's bottom face
      // (face 4), sorted: the same for every cell over one footprint,
      // whatever the order of its vertices.
      Footprint
      footprint(const Cell &cell, const std::vector<Point<3>> &initial_vertices)
      {
        Footprint corners;
        for (unsigned int v = 0; v < 4; ++v)
        {
          const Point<3> &X = initial_vertices[cell->face(4)->vertex_index(v)];
          corners[v]        = {X[0], X[1]};
        }
        std::sort(corners.begin(), corners.end());
        return corners;
      }

      // Whether p lies in the bounding box of the footprint.
      bool
      inside(const Point<2> &p, const Footprint &corners)
      {
        double x[2] = {corners[0].first, corners[0].first};
        double y[2] = {corners[0].second, corners[0].second};
        for (const auto &[cx, cy] : corners)
        {
          x[0] = std::min(x[0], cx);
          x[1] = std::max(x[1], cx);
          y[0] = std::min(y[0], cy);
          y[1] = std::max(y[1], cy);
        }
        return p[0] >= x[0] && p[0] <= x[1] && p[1] >= y[0] && p[1] <= y[1];
      }
    } // namespace


    std::string
    surface_name(const SheetSurface surface)
    {
      constexpr const char *names[] = {"bottom", "mid", "top"};
      return names[unsigned(surface)];
    }


    ColumnStrains::SurfacePoint::SurfacePoint(
      const std::array<unsigned int, 4> &face_vertices,
      const std::array<double, 4>       &weights,
      const std::vector<Point<3>>       &initial_vertices)
        : vertices(face_vertices)
        // The bilinear weights (1-xi)(1-eta), xi(1-eta), (1-xi)eta, xi eta.
        , xi(weights[1] + weights[3])
        , eta(weights[2] + weights[3])
    {
      // With the identity, tangents() gives d X / d(xi, eta); the in-plane
      // part inverted turns every tangent into d x / d(X, Y), a frame that
      // the bottom and the top surface share (the mid surface's).
      inverse_jacobian[0][0] = inverse_jacobian[1][1] = 1.;
      const std::array<Tensor<1, 3>, 2> reference = tangents(initial_vertices);
      Tensor<2, 2>                      jacobian;
      for (unsigned int k = 0; k < 2; ++k)
        for (unsigned int i = 0; i < 2; ++i)
          jacobian[k][i] = reference[i][k];
      inverse_jacobian = invert(jacobian);
      initial_tangents = tangents(initial_vertices);
    }


    std::array<Tensor<1, 3>, 2>
    ColumnStrains::SurfacePoint::tangents(const std::vector<Point<3>> &x) const
    {
      const auto  &v = vertices;
      Tensor<1, 3> d_xi
        = (1. - eta) * (x[v[1]] - x[v[0]]) + eta * (x[v[3]] - x[v[2]]);
      Tensor<1, 3> d_eta
        = (1. - xi) * (x[v[2]] - x[v[0]]) + xi * (x[v[3]] - x[v[1]]);
      const Tensor<2, 2> &J = inverse_jacobian;
      return {
        {d_xi * J[0][0] + d_eta * J[1][0], d_xi * J[0][1] + d_eta * J[1][1]}};
    }


    ColumnStrains::Column
    ColumnStrains::make_column(const Cell                  &bottom,
                               const std::vector<Point<3>> &initial_vertices,
                               const blank::SheetThickness &surfaces)
    {
      Column column;
      for (unsigned int v = 0; v < 4; ++v)
      {
        const Point<3> &X = initial_vertices[bottom->face(4)->vertex_index(v)];
        column.centre += Tensor<1, 2>({X[0], X[1]}) / 4.;
      }
      const auto location = surfaces.locate(column.centre);
      if (!location)
        throw InputError("the forming limits: the column of cells at (X, Y) "
                         "= ("
                         + io::number_text(column.centre[0]) + ", "
                         + io::number_text(column.centre[1])
                         + ") lies over no face of the sheet's bottom and "
                           "top surfaces");
      column.location = *location;
      column.bottom   = SurfacePoint(location->bottom_vertices,
                                   location->bottom_weights,
                                   initial_vertices);
      column.top      = SurfacePoint(location->top_vertices,
                                location->top_weights,
                                initial_vertices);
      return column;
    }


    void
    ColumnStrains::set_up(const Triangulation<3>      &mesh,
                          const std::vector<Point<3>> &initial_vertices,
                          const blank::SheetThickness &surfaces)
    {
      columns.clear();
      lowest.clear();
      column_of_id.clear();
      cell_column.assign(mesh.n_active_cells(), numbers::invalid_unsigned_int);
      // Stacks over the same footprint are one column; a stack that ends at
      // a refined face (a coarse cell above or below cells refined
      // isotropically) is no column of its own: its footprint is the finer
      // columns' (D173).
      std::map<Footprint, unsigned int>                    column_of_footprint;
      std::vector<std::pair<std::vector<Cell>, Footprint>> covered;
      for (const auto &cell : mesh.active_cell_iterators())
      {
        if (cell_column[cell->active_cell_index()]
            != numbers::invalid_unsigned_int)
          continue;
        Cell bottom = cell;
        while (const auto below = stacked_neighbour(bottom, 4))
          bottom = *below;
        std::vector<Cell> stack;
        for (std::optional<Cell> c = bottom; c; c = stacked_neighbour(*c, 5))
          stack.push_back(*c);
        const Footprint corners = footprint(bottom, initial_vertices);
        if (bottom->face(4)->has_children()
            || stack.back()->face(5)->has_children())
        {
          for (const Cell &c : stack)
            cell_column[c->active_cell_index()] = columns.size();
          covered.emplace_back(stack, corners);
          continue;
        }
        const auto [found, is_new]
          = column_of_footprint.emplace(corners, columns.size());
        if (is_new)
        {
          columns.push_back(make_column(bottom, initial_vertices, surfaces));
          lowest.push_back(bottom);
        }
        assign(stack, found->second);
      }
      // A covered stack's cells (their VTU values) belong to the first
      // column whose centre lies on its footprint.
      for (const auto &[stack, corners] : covered)
      {
        unsigned int k = 0;
        while (k < columns.size() && !inside(columns[k].centre, corners))
          ++k;
        if (k == columns.size())
        {
          columns.push_back(
            make_column(stack.front(), initial_vertices, surfaces));
          lowest.push_back(stack.front());
        }
        assign(stack, k);
      }
    }


    void
    ColumnStrains::assign(const std::vector<Cell> &stack,
                          const unsigned int       column)
    {
      for (const Cell &c : stack)
      {
        cell_column[c->active_cell_index()] = column;
        column_of_id[c->id()]               = column;
      }
    }


    unsigned int
    ColumnStrains::n_columns() const
    {
      return columns.size();
    }


    const std::vector<unsigned int> &
    ColumnStrains::column_of_cell() const
    {
      return cell_column;
    }


    const Point<2> &
    ColumnStrains::centre(const unsigned int column) const
    {
      return columns[column].centre;
    }


    std::vector<unsigned int>
    ColumnStrains::inherited_from(const ColumnStrains &previous) const
    {
      std::vector<unsigned int> result(columns.size(),
                                       numbers::invalid_unsigned_int);
      for (unsigned int k = 0; k < columns.size(); ++k)
        for (Triangulation<3>::cell_iterator cell = lowest[k];;
             cell                                 = cell->parent())
        {
          const auto found = previous.column_of_id.find(cell->id());
          if (found != previous.column_of_id.end())
          {
            result[k] = found->second;
            break;
          }
          if (cell->level() == 0)
            break;
        }
      return result;
    }


    std::vector<ColumnStrain>
    ColumnStrains::compute(const std::vector<Point<3>> &vertices,
                           const blank::SheetThickness &surfaces,
                           const double                 initial_thickness) const
    {
      std::vector<ColumnStrain> result(columns.size());
      for (unsigned int k = 0; k < columns.size(); ++k)
      {
        const Column &column = columns[k];
        const auto    bottom = column.bottom.tangents(vertices);
        const auto    top    = column.top.tangents(vertices);
        // The mid surface x = (x_top + x_bottom)/2 over (X, Y): its
        // tangents are the means, at t = 0 and now.
        std::array<Tensor<1, 3>, 2> mid, initial_mid;
        for (unsigned int i = 0; i < 2; ++i)
        {
          mid[i]         = 0.5 * (bottom[i] + top[i]);
          initial_mid[i] = 0.5
                           * (column.bottom.initial_tangents[i]
                              + column.top.initial_tangents[i]);
        }
        auto &strain = result[k].surfaces;
        strain[unsigned(SheetSurface::bottom)]
          = formability::surface_strain(column.bottom.initial_tangents, bottom);
        strain[unsigned(SheetSurface::mid)]
          = formability::surface_strain(initial_mid, mid);
        strain[unsigned(SheetSurface::top)]
          = formability::surface_strain(column.top.initial_tangents, top);
        result[k].thickness_strain = std::log(
          surfaces.thickness(column.location, vertices) / initial_thickness);
      }
      return result;
    }
  } // namespace postprocess
} // namespace deepdraw
