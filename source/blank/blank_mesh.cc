// The blank's mesh for each Blank outline (doc/user_guide.md §2.1, D71).
#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deepdraw/blank/blank_geometry.h>
#include <deepdraw/blank/gmsh_file_check.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <sstream>

namespace deepdraw
{
  namespace blank
  {
    namespace
    {
      // Quarter of the unit disc (x, y >= 0): an inner block of m x m cells
      // inside the arc r = a (transfinite interpolation of its four sides:
      // the axes and two 45-degree arcs) and two ring blocks of k x m polar
      // cells from r = a to 1, equal angles, equal radial steps. The ring,
      // where the rim and its ears are, is the same at every angle up to the
      // reflection about 45 degrees, so that the mesh favours no direction
      // of the sheet there (D71). a = 1/2 and m = 0.6 n make the rim cells
      // about square ((1 - a)/k against (pi/4)/m) and keep the aspect ratios
      // of all cells within about 2.
      void
      add_quarter_disc(const unsigned int        m,
                       const unsigned int        k,
                       std::vector<Point<2>>    &vertices,
                       std::vector<CellData<2>> &cells)
      {
        const double a = 0.5;
        // A block of (n0 + 1) x (n1 + 1) vertices from position(i, j).
        const auto add_block = [&](const unsigned int n0,
                                   const unsigned int n1,
                                   const auto        &position)
        {
          const unsigned int first = vertices.size();
          for (unsigned int j = 0; j <= n1; ++j)
            for (unsigned int i = 0; i <= n0; ++i)
              vertices.push_back(position(i, j));
          for (unsigned int j = 0; j < n1; ++j)
            for (unsigned int i = 0; i < n0; ++i)
            {
              CellData<2>        cell;
              const unsigned int v = first + i + j * (n0 + 1);
              cell.vertices        = {v, v + 1, v + n0 + 1, v + n0 + 2};
              cells.push_back(cell);
            }
        };
        const auto polar = [](const double r, const double phi)
        { return Point<2>(r * std::cos(phi), r * std::sin(phi)); };
        // Inner block: Coons patch of the sides v = 0 (x axis), u = 0 (y
        // axis), u = 1 (arc 0 to 45 deg), v = 1 (arc 90 to 45 deg).
        add_block(m,
                  m,
                  [&](const unsigned int i, const unsigned int j)
                  {
                    const double   u = double(i) / m, v = double(j) / m;
                    const Point<2> bottom(a * u, 0.), left(0., a * v);
                    const Point<2> right = polar(a, M_PI / 4. * v);
                    const Point<2> top   = polar(a, M_PI / 2. - M_PI / 4. * u);
                    const Point<2> corner_x(a, 0.), corner_y(0., a);
                    const Point<2> corner = polar(a, M_PI / 4.);
                    return Point<2>((1. - v) * bottom + v * top
                                    + (1. - u) * left + u * right
                                    - u * (1. - v) * corner_x
                                    - (1. - u) * v * corner_y - u * v * corner);
                  });
        // Ring from r = a (index 0) to the arc (index k), 0 to 45 deg.
        add_block(k,
                  m,
                  [&](const unsigned int r, const unsigned int j)
                  { return polar(a + (1. - a) * r / k, M_PI / 4. * j / m); });
        // Ring 90 to 45 deg.
        add_block(m,
                  k,
                  [&](const unsigned int i, const unsigned int r) {
                    return polar(a + (1. - a) * r / k,
                                 M_PI / 2. - M_PI / 4. * i / m);
                  });
      }


      // Boundary ids of the extruded sheet by position: bottom 4, top 5, the
      // symmetry planes x = 0 -> 0 and y = 0 -> 2, the rest of the rim 1.
      void
      set_boundary_ids(Triangulation<3> &triangulation,
                       const double      thickness,
                       const bool        plane_x,
                       const bool        plane_y,
                       const double      tolerance)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
            {
              bool bottom = true, top = true, on_x = true, on_y = true;
              for (const unsigned int v : face->vertex_indices())
              {
                const Point<3> &x = face->vertex(v);
                bottom            = bottom && std::abs(x[2]) <= tolerance;
                top  = top && std::abs(x[2] - thickness) <= tolerance;
                on_x = on_x && std::abs(x[0]) <= tolerance;
                on_y = on_y && std::abs(x[1]) <= tolerance;
              }
              face->set_boundary_id(bottom              ? 4
                                    : top               ? 5
                                    : (plane_x && on_x) ? 0
                                    : (plane_y && on_y) ? 2
                                                        : 1);
            }
      }
    } // namespace


    unsigned int
    BlankGeometry::disc_square_cells(const unsigned int n)
    {
      return std::clamp<unsigned int>(std::lround(0.6 * n), 1, n - 1);
    }


    void
    BlankGeometry::create_disc_mesh(Triangulation<2> &plane) const
    {
      const unsigned int       m = disc_square_cells(elements_along_radius);
      const unsigned int       k = elements_along_radius - m;
      std::vector<Point<2>>    quarter_vertices, vertices;
      std::vector<CellData<2>> quarter_cells, cells;
      add_quarter_disc(m, k, quarter_vertices, quarter_cells);

      // The modelled quadrants, as quarter turns of the first one (exact):
      // turn q covers x > 0 for q = 0, 3 and y > 0 for q = 0, 1.
      std::vector<unsigned int> turns;
      for (const unsigned int q : {0u, 1u, 2u, 3u})
        if ((!symmetry_plane_x || q == 0 || q == 3)
            && (!symmetry_plane_y || q == 0 || q == 1))
          turns.push_back(q);
      for (const unsigned int turn : turns)
      {
        const unsigned int first = vertices.size();
        for (Point<2> p : quarter_vertices)
        {
          for (unsigned int q = 0; q < turn; ++q)
            p = Point<2>(-p[1], p[0]);
          vertices.push_back(p);
        }
        for (CellData<2> cell : quarter_cells)
        {
          for (unsigned int &v : cell.vertices)
            v += first;
          cells.push_back(cell);
        }
      }
      SubCellData               no_subcells;
      std::vector<unsigned int> considered;
      GridTools::delete_duplicated_vertices(vertices,
                                            cells,
                                            no_subcells,
                                            considered,
                                            1e-10);
      GridTools::consistently_order_cells(cells);

      // The unit disc mapped onto the outline along rays from the origin.
      for (Point<2> &p : vertices)
        p *= shape.radius(std::atan2(p[1], p[0]));
      plane.create_triangulation(vertices, cells, no_subcells);
    }


    namespace
    {
      // Why a quadrilateral cannot make a valid hexahedron, or "" (D178):
      // the Jacobian of the bilinear map is positive everywhere if it is at
      // the four corners, i.e. the cell is convex and counterclockwise.
      std::string
      corner_fault(const Triangulation<2>::active_cell_iterator &cell)
      {
        // deal.II's vertex order: 0 1 below, 2 3 above; round the cell
        // counterclockwise: 0 1 3 2.
        const unsigned int round[4] = {0, 1, 3, 2};
        unsigned int       n_bad = 0, n_negative = 0, bad = 0;
        for (unsigned int k = 0; k < 4; ++k)
        {
          const Point<2>    &before = cell->vertex(round[(k + 3) % 4]);
          const Point<2>    &here   = cell->vertex(round[k]);
          const Point<2>    &after  = cell->vertex(round[(k + 1) % 4]);
          const Tensor<1, 2> a = after - here, b = before - here;
          const double       turn = a[0] * b[1] - a[1] * b[0];
          n_negative += turn < 0.;
          if (!(turn > 0.))
            ++n_bad, bad = round[k];
        }
        std::ostringstream corner;
        corner << "(" << cell->vertex(bad)[0] << ", " << cell->vertex(bad)[1]
               << ")";
        if (n_negative == 4)
          return " is inverted (its corners run clockwise)";
        if (n_bad == 4)
          return ""; // no area at all: reported as such
        if (n_bad == 1)
          return " is not convex: its corner at " + corner.str()
                 + " points inwards (180 degrees or more)";
        if (n_bad > 1)
          return " crosses itself (a bow-tie: its edges cross) or is "
                 "folded; a cell must be a convex quadrilateral with its "
                 "corners counterclockwise";
        return "";
      }
    } // namespace


    void
    BlankGeometry::read_plane_mesh()
    {
      auto               mesh = std::make_shared<Triangulation<2>>();
      const std::string  name = io::one_line(mesh_file, 300);
      std::istringstream in(read_gmsh_text(mesh_file));
      try
      {
        GridIn<2> grid_in;
        grid_in.attach_triangulation(*mesh);
        grid_in.read_msh(in);
      }
      catch (const ExceptionBase &error)
      {
        // deal.II's message without its banner and stack trace.
        std::string       reason = error.what();
        const std::string info   = "Additional information:";
        if (const auto k = reason.find(info); k != std::string::npos)
          reason = reason.substr(k + info.size());
        reason = reason.substr(0, reason.find("Stacktrace"));
        throw InputError(name + ": not a usable two-dimensional Gmsh mesh: "
                         + io::one_line(reason, 500));
      }
      catch (const std::exception &error)
      {
        throw InputError(name + ": not a usable two-dimensional Gmsh mesh: "
                         + io::one_line(error.what(), 500));
      }
      if (mesh->n_active_cells() == 0)
        throw InputError(name + ": the mesh has no cells");
      double extent = 0.;
      for (const Point<2> &p : mesh->get_vertices())
        extent = std::max(extent, p.norm());
      const double tolerance = 1e-9 * extent;
      for (const auto &cell : mesh->active_cell_iterators())
      {
        const std::string which
          = name + ": cell " + std::to_string(cell->active_cell_index() + 1);
        if (cell->reference_cell() != ReferenceCells::Quadrilateral)
          throw InputError(which
                           + " is not a quadrilateral (the sheet is made "
                             "of hexahedra: mesh the blank with "
                             "quadrilaterals, e.g. Gmsh's Recombine)");
        for (const unsigned int v : cell->vertex_indices())
          if ((symmetry_plane_x && cell->vertex(v)[0] < -tolerance)
              || (symmetry_plane_y && cell->vertex(v)[1] < -tolerance))
            throw InputError(which
                             + " lies on the far side of a symmetry plane "
                               "(Geometry/Symmetry planes): the mesh must be "
                               "the modelled part");
        if (const std::string fault = corner_fault(cell); !fault.empty())
          throw InputError(which + fault);
        if (!(cell->measure() > 0.))
          throw InputError(which + " has no positive area");
      }
      const BoundingBox<2> box(mesh->get_vertices());
      length     = box.side_length(0);
      width      = box.side_length(1);
      plane_mesh = mesh;
    }


    void
    BlankGeometry::create_mesh(Triangulation<3> &triangulation) const
    {
      if (outline == Outline::rectangle)
      {
        const std::vector<unsigned int> repetitions
          = {elements_along_x, elements_along_y, layers_through_thickness};
        GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                  repetitions,
                                                  Point<3>(0, 0, 0),
                                                  Point<3>(length,
                                                           width,
                                                           thickness),
                                                  /*colorize=*/true);
      }
      else
      {
        Triangulation<2> disc;
        if (outline != Outline::gmsh)
          create_disc_mesh(disc);
        const Triangulation<2> &plane
          = outline == Outline::gmsh ? *plane_mesh : disc;
        GridGenerator::extrude_triangulation(plane,
                                             layers_through_thickness + 1,
                                             thickness,
                                             triangulation);
        set_boundary_ids(triangulation,
                         thickness,
                         symmetry_plane_x,
                         symmetry_plane_y,
                         1e-9 * largest_extent());
      }
      if (mesh_distortion > 0.)
        GridTools::distort_random(mesh_distortion,
                                  triangulation,
                                  /*keep_boundary=*/true);
    }
  } // namespace blank
} // namespace deepdraw
