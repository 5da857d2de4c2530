// The thickness of the sheet at a reference in-plane point (X, Y), on any
// hexahedral sheet mesh: unstructured in the plane, with hanging nodes,
// with different layer counts under different parts of the surface
// (doc/theory.md §6, D72). The bottom (boundary id 4) and top (id 5) faces
// containing (X, Y) in the reference configuration are found once; their
// current positions interpolated bilinearly give x_bottom and x_top, and
// the thickness is |(x_top - x_bottom) . n| / |n| with n the bilinear
// interpolation of the vertex normals (the sum of the unit normals of the
// top faces at a vertex, minus that of the bottom faces).
#ifndef deepdraw_blank_sheet_thickness_h
#define deepdraw_blank_sheet_thickness_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <optional>
#include <vector>

namespace deepdraw
{
  namespace blank
  {
    using namespace dealii;

    class SheetThickness
    {
    public:
      // A reference point on the bottom and on the top surface: the
      // vertices of the face containing it and their bilinear weights.
      struct Location
      {
        std::array<unsigned int, 4> bottom_vertices{};
        std::array<double, 4>       bottom_weights{};
        std::array<unsigned int, 4> top_vertices{};
        std::array<double, 4>       top_weights{};
      };

      // The bottom and top faces of the active cells; reference_vertices
      // (indexed like triangulation.get_vertices()) is the configuration
      // in which points are located, usually the initial mesh.
      SheetThickness(const Triangulation<3>      &triangulation,
                     const std::vector<Point<3>> &reference_vertices);

      // Where (X, Y) lies; empty if not over both a bottom and a top face
      // (points on a face's edge, within 1e-9 of the mesh size, count).
      std::optional<Location>
      locate(const Point<2> &X) const;

      // The vertex normals of the configuration `vertices` (call after
      // every change of the vertex positions, before thickness()).
      void
      update(const std::vector<Point<3>> &vertices);
      // Thickness at a location in the configuration `vertices`, with the
      // normals of the last update() (of the same vertices).
      double
      thickness(const Location              &location,
                const std::vector<Point<3>> &vertices) const;
      // Midpoint of the bottom and top surface points at the location.
      static Point<3>
      mid_surface(const Location              &location,
                  const std::vector<Point<3>> &vertices);

      // Distances s along the ray s d from the origin (d a unit vector in
      // the plane) where it crosses an edge of a bottom face, from where it
      // first enters the sheet to where it first leaves it (both
      // included): the points of a profile; the last is the outline.
      std::vector<double>
      ray_crossings(const Tensor<1, 2> &direction) const;

    private:
      // Faces of one surface with their reference corners in the plane and
      // a grid of bins over them for locate().
      struct Surface
      {
        std::vector<std::array<unsigned int, 4>> faces;
        std::vector<std::array<Point<2>, 4>>     corners;
        // +1 if the face's (v3 - v0) x (v2 - v1) points out of its cell.
        std::vector<double>                    orientation;
        Point<2>                               origin;
        double                                 bin_size = 1.;
        unsigned int                           n_bins   = 1;
        std::vector<std::vector<unsigned int>> bins;

        void
        make_bins(double tolerance);
        // Face containing X and its weights; false if none.
        bool
        find(const Point<2>              &X,
             double                       tolerance,
             std::array<unsigned int, 4> &vertices,
             std::array<double, 4>       &weights) const;
      };

      void
      add_face(Surface                                      &surface,
               const Triangulation<3>::face_iterator        &face,
               const Triangulation<3>::active_cell_iterator &cell,
               const std::vector<Point<3>> &reference_vertices);

      Surface                   bottom, top;
      double                    tolerance = 0.;
      std::vector<Tensor<1, 3>> vertex_normal;
    };
  } // namespace blank
} // namespace deepdraw

#endif
