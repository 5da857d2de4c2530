// The blank: a rectangular sheet [0, Length] x [0, Width] x [0, Thickness]
// meshed with hexahedra, Elements along x/y in the plane and Layers through
// thickness through the sheet. Boundary ids (colorized box): x = 0 -> 0,
// x = Length -> 1, y = 0 -> 2, y = Width -> 3, bottom z = 0 -> 4, top -> 5.
#ifndef deepdraw_problem_blank_geometry_h
#define deepdraw_problem_blank_geometry_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace problem
  {
    using namespace dealii;

    // Names of the six faces of the blank, indexed by boundary id.
    extern const std::array<std::string, 6> face_names;

    struct BlankGeometry
    {
      double       length                   = 75.;
      double       width                    = 75.;
      double       thickness                = 0.81;
      unsigned int elements_along_x         = 25;
      unsigned int elements_along_y         = 25;
      unsigned int layers_through_thickness = 2;
      bool         symmetry_plane_x         = true; // plane x = 0
      bool         symmetry_plane_y         = true; // plane y = 0
      double       mesh_distortion          = 0.;

      // Largest allowed Length, Width, Thickness (mm) and element count
      // along one direction (D50).
      static constexpr double max_extent   = 1e4;
      static constexpr int    max_elements = 100000;

      // Entries of subsection Geometry.
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      // max(Length, Width, Thickness) and the diagonal of the blank (mm):
      // the scales the bounds of lengths elsewhere refer to.
      double
      largest_extent() const;
      double
      diagonal() const;
      // Number of cells of the mesh.
      double
      n_cells() const;

      // The mesh, and for every vertex the through-thickness column it
      // belongs to (i + j (nx + 1)) and its layer (0 = bottom), found before
      // any distortion.
      void
      create_mesh(Triangulation<3>          &triangulation,
                  std::vector<unsigned int> &vertex_column,
                  std::vector<unsigned int> &vertex_layer) const;
    };
  } // namespace problem
} // namespace deepdraw

#endif
