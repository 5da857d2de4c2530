#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deepdraw/blank/blank_geometry.h>
#include <deepdraw/io/input_error.h>
#include <filesystem>

namespace deepdraw
{
  namespace blank
  {
    static_assert(max_outline_radius == BlankGeometry::max_extent,
                  "an outline's corners lie within a blank's extent");

    const std::array<std::string, 6> face_names
      = {{"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}};

    void
    BlankGeometry::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry("Blank outline",
                        "rectangle",
                        Patterns::Selection("rectangle|circle|polygon|gmsh"),
                        "In-plane shape of the blank (doc/user_guide.md "
                        "§2.1): rectangle [0, Length] x [0, Width]; circle "
                        "of Diameter about the origin; polygon of Outline "
                        "file about the origin (star-shaped about it); "
                        "gmsh: the quadrilaterals of Mesh file extruded "
                        "through the thickness. Symmetry planes cut the "
                        "circle and the polygon; the rectangle and the Gmsh "
                        "mesh are the modelled part.");
      prm.declare_entry("Diameter",
                        "100",
                        Patterns::Double(0., max_extent),
                        "Diameter of the circular blank, mm (0 < Diameter "
                        "<= 10000).");
      prm.declare_entry("Outline file",
                        "",
                        Patterns::Anything(),
                        "Blank outline = polygon: file of the outline "
                        "corners, one 'x y' (mm) per line, '#' comments, "
                        "closed implicitly; relative to the prm file's "
                        "directory.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::Anything(),
                        "Blank outline = gmsh: two-dimensional Gmsh mesh "
                        "(.msh) of the modelled part of the blank in the "
                        "plane z = 0, quadrilaterals only; relative to the "
                        "prm file's directory.");
      prm.declare_entry("Elements along radius",
                        "12",
                        Patterns::Integer(2, 10000),
                        "Circle and polygon: elements along a radius of the "
                        "disc mesh (2 to 10000); a quadrant has about 1.6 "
                        "times as many along its arc.");
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
    BlankGeometry::parse_parameters(ParameterHandler  &prm,
                                    const std::string &input_directory)
    {
      prm.enter_subsection("Geometry");
      const std::string outline_name = prm.get("Blank outline");
      outline                  = outline_name == "circle"    ? Outline::circle
                                 : outline_name == "polygon" ? Outline::polygon
                                 : outline_name == "gmsh"    ? Outline::gmsh
                                                          : Outline::rectangle;
      diameter                 = prm.get_double("Diameter");
      outline_file             = prm.get("Outline file");
      mesh_file                = prm.get("Mesh file");
      elements_along_radius    = prm.get_integer("Elements along radius");
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
      read_outline(input_directory);
    }


    void
    BlankGeometry::read_outline(const std::string &input_directory)
    {
      const auto resolve = [&](const std::string &file, const char *entry)
      {
        if (Utilities::trim(file).empty())
          throw InputError(
            std::string("Geometry/") + entry + " is empty; Blank outline = "
            + (outline == Outline::polygon ? "polygon" : "gmsh") + " needs it");
        return std::filesystem::path(file).is_absolute()
                 ? file
                 : (std::filesystem::path(input_directory) / file).string();
      };
      if (outline == Outline::rectangle)
        return;
      if (outline == Outline::gmsh)
      {
        mesh_file = resolve(mesh_file, "Mesh file");
        read_plane_mesh();
        return;
      }
      if (outline == Outline::circle)
      {
        if (!(diameter > 0.) || !(diameter <= max_extent))
          throw InputError("Geometry/Diameter must be a positive length in "
                           "mm (0 < Diameter <= 10000), got "
                           + std::to_string(diameter));
        shape = BlankOutline::circle(diameter);
      }
      else
      {
        outline_file = resolve(outline_file, "Outline file");
        shape        = BlankOutline::read(outline_file);
      }
      // The modelled part's extents (the scales of D50 and the check of
      // prescribed displacements): the largest radius along each axis.
      const double r = shape.max_radius();
      length         = symmetry_plane_x ? r : 2. * r;
      width          = symmetry_plane_y ? r : 2. * r;
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
      return n_plane_cells() * layers_through_thickness;
    }


    double
    BlankGeometry::n_plane_cells() const
    {
      // As doubles: the product of counts up to 1e5 overflows an unsigned
      // int.
      if (outline == Outline::rectangle)
        return double(elements_along_x) * elements_along_y;
      if (outline == Outline::gmsh)
        return plane_mesh ? plane_mesh->n_active_cells() : 0.;
      const unsigned int quadrants
        = (symmetry_plane_x ? 1 : 2) * (symmetry_plane_y ? 1 : 2);
      const double m = disc_square_cells(elements_along_radius);
      const double k = elements_along_radius - m;
      return quadrants * (m * m + 2. * m * k);
    }


    double
    BlankGeometry::n_plane_vertices() const
    {
      if (outline == Outline::rectangle)
        return double(elements_along_x + 1) * (elements_along_y + 1);
      if (outline == Outline::gmsh)
        return plane_mesh ? plane_mesh->n_used_vertices() : 0.;
      // A quadrilateral mesh has about one vertex per cell, plus the rim.
      return n_plane_cells() + 4. * elements_along_radius + 1.;
    }
  } // namespace blank
} // namespace deepdraw
