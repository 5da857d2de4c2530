#include <algorithm>
#include <cmath>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/problem/blank_geometry.h>

namespace deepdraw
{
  namespace problem
  {
    const std::array<std::string, 6> face_names
      = {{"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}};

    void
    BlankGeometry::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      // Upper bounds (D50): 10 m of blank, and a mesh whose memory is
      // estimated before it is made (memory_estimate.h).
      prm.declare_entry("Length",
                        "75",
                        Patterns::Double(0., max_extent),
                        "Extent of the blank along x (rolling direction), mm "
                        "(0 < Length <= 10000). With a symmetry plane x = 0 "
                        "this is half the blank.");
      prm.declare_entry("Width",
                        "75",
                        Patterns::Double(0., max_extent),
                        "Extent of the blank along y, mm (0 < Width <= "
                        "10000).");
      prm.declare_entry("Thickness",
                        "0.81",
                        Patterns::Double(0., max_extent),
                        "Initial sheet thickness (along z), mm (0 < "
                        "Thickness <= 10000).");
      prm.declare_entry("Elements along x",
                        "25",
                        Patterns::Integer(1, max_elements),
                        "Number of elements along x (1 to 100000; the "
                        "memory the mesh needs is checked against what is "
                        "available).");
      prm.declare_entry("Elements along y",
                        "25",
                        Patterns::Integer(1, max_elements),
                        "Number of elements along y (1 to 100000).");
      prm.declare_entry("Layers through thickness",
                        "2",
                        Patterns::Integer(1, max_elements),
                        "Number of element layers through the thickness "
                        "(1 to 100000; two or more recommended in "
                        "bending).");
      prm.declare_entry("Symmetry planes",
                        "x, y",
                        Patterns::MultipleSelection("x|y"),
                        "Symmetry planes of the model: 'x' means the plane "
                        "x = 0 (u_x = 0 there), 'y' the plane y = 0. Leave "
                        "empty for none.");
      prm.declare_entry("Mesh distortion",
                        "0",
                        Patterns::Double(0., 0.4),
                        "Random displacement of interior vertices as a "
                        "fraction of the element size (for tests of "
                        "distorted meshes); 0 = regular mesh.");
      prm.leave_subsection();
    }


    void
    BlankGeometry::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      length                   = prm.get_double("Length");
      width                    = prm.get_double("Width");
      thickness                = prm.get_double("Thickness");
      elements_along_x         = prm.get_integer("Elements along x");
      elements_along_y         = prm.get_integer("Elements along y");
      layers_through_thickness = prm.get_integer("Layers through thickness");
      const std::string planes = prm.get("Symmetry planes");
      symmetry_plane_x         = planes.find('x') != std::string::npos;
      symmetry_plane_y         = planes.find('y') != std::string::npos;
      mesh_distortion          = prm.get_double("Mesh distortion");
      prm.leave_subsection();

      const std::pair<const char *, double> extents[]
        = {{"Length", length}, {"Width", width}, {"Thickness", thickness}};
      for (const auto &[name, value] : extents)
        if (!(value > 0.) || !(value <= max_extent))
          throw InputError("Geometry/" + std::string(name)
                           + " must be a positive length in mm (0 < " + name
                           + " <= 10000), got " + std::to_string(value));
    }


    double
    BlankGeometry::largest_extent() const
    {
      return std::max({length, width, thickness});
    }


    double
    BlankGeometry::diagonal() const
    {
      return std::sqrt(length * length + width * width + thickness * thickness);
    }


    double
    BlankGeometry::n_cells() const
    {
      // As a double: the product of three counts up to 1e5 overflows an
      // unsigned int.
      return double(elements_along_x) * elements_along_y
             * layers_through_thickness;
    }


    void
    BlankGeometry::create_mesh(Triangulation<3>          &triangulation,
                               std::vector<unsigned int> &vertex_column,
                               std::vector<unsigned int> &vertex_layer) const
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

      const double hx       = length / elements_along_x;
      const double hy       = width / elements_along_y;
      const double hz       = thickness / layers_through_thickness;
      const auto  &vertices = triangulation.get_vertices();
      vertex_column.resize(vertices.size());
      vertex_layer.resize(vertices.size());
      for (unsigned int v = 0; v < vertices.size(); ++v)
      {
        const unsigned int i = std::lround(vertices[v][0] / hx);
        const unsigned int j = std::lround(vertices[v][1] / hy);
        vertex_column[v]     = i + j * (elements_along_x + 1);
        vertex_layer[v]      = std::lround(vertices[v][2] / hz);
      }

      if (mesh_distortion > 0.)
        GridTools::distort_random(mesh_distortion,
                                  triangulation,
                                  /*keep_boundary=*/true);
    }
  } // namespace problem
} // namespace deepdraw
