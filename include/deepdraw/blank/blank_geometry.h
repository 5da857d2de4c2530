// The blank (doc/user_guide.md §2.1): a sheet of thickness Thickness (along
// z, bottom z = 0) whose in-plane shape is the Blank outline: the rectangle
// [0, Length] x [0, Width] (Elements along x/y), a circle of diameter
// Diameter or the polygon of an outline file about the origin (a disc mesh
// mapped onto it, Elements along radius), or a two-dimensional Gmsh mesh;
// Layers through thickness hexahedra through the sheet. Symmetry planes
// x = 0, y = 0 cut the circle and the polygon to the modelled part; the
// rectangle and the Gmsh mesh are the modelled part. Boundary ids: x = 0 -> 0,
// y = 0 -> 2, bottom z = 0 -> 4, top -> 5, the rest of the rim -> 1 (the
// rectangle's x = Length; y = Width -> 3).
#ifndef deepdraw_blank_blank_geometry_h
#define deepdraw_blank_blank_geometry_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/blank/blank_outline.h>
#include <memory>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace blank
  {
    using namespace dealii;

    // Names of the six faces of the blank, indexed by boundary id.
    extern const std::array<std::string, 6> face_names;

    struct BlankGeometry
    {
      enum class Outline
      {
        rectangle,
        circle,
        polygon,
        gmsh
      };

      Outline      outline                  = Outline::rectangle;
      double       length                   = 75.;
      double       width                    = 75.;
      double       diameter                 = 100.;
      double       thickness                = 0.81;
      unsigned int elements_along_x         = 25;
      unsigned int elements_along_y         = 25;
      unsigned int elements_along_radius    = 12;
      unsigned int layers_through_thickness = 2;
      bool         symmetry_plane_x         = true; // plane x = 0
      bool         symmetry_plane_y         = true; // plane y = 0
      double       mesh_distortion          = 0.;
      // Outline file / Mesh file as given and resolved against the input
      // directory.
      std::string outline_file;
      std::string mesh_file;
      // The circle or polygon (outline circle, polygon).
      BlankOutline shape;
      // The two-dimensional mesh read from Mesh file (outline gmsh).
      std::shared_ptr<const Triangulation<2>> plane_mesh;

      // Largest allowed Length, Width, Thickness (mm) and element count
      // along one direction (D50).
      static constexpr double max_extent   = 1e4;
      static constexpr int    max_elements = 100000;

      // Entries of subsection Geometry. parse_parameters reads and checks
      // the outline or mesh file (InputError naming file and line); file
      // names are relative to input_directory. For the outlines other than
      // the rectangle, Length and Width become the extents of the modelled
      // part in x and y.
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler  &prm,
                       const std::string &input_directory = ".");

      // max(Length, Width, Thickness) and the diagonal of the blank (mm):
      // the scales the bounds of lengths elsewhere refer to.
      double
      largest_extent() const;
      double
      diagonal() const;
      // Number of cells of the mesh, and of its cells and vertices in the
      // plane (one layer).
      double
      n_cells() const;
      double
      n_plane_cells() const;
      double
      n_plane_vertices() const;

      // The mesh (blank_mesh.cc); throws InputError if the Gmsh mesh does
      // not make a valid sheet.
      void
      create_mesh(Triangulation<3> &triangulation) const;

      // Cells along each side of the inner square of a quarter disc of n
      // elements along its radius (the other n - m are in the ring).
      static unsigned int
      disc_square_cells(unsigned int n);

    private:
      // Reads the outline or the mesh file of the outline (parse_parameters).
      void
      read_outline(const std::string &input_directory);
      // The two-dimensional mesh of a circle or polygon outline: a unit
      // quarter disc per modelled quadrant, mapped radially (D71).
      void
      create_disc_mesh(Triangulation<2> &plane) const;
      // Reads Mesh file into plane_mesh and checks it (quadrilaterals only,
      // inside the modelled quadrants).
      void
      read_plane_mesh();
    };
  } // namespace blank
} // namespace deepdraw

#endif
