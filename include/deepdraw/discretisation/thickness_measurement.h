// The current thickness of the sheet at every vertex, measured as a real
// distance at the vertex's initial (X, Y) on the sheet's surfaces
// (blank::SheetThickness, doc/theory.md §6).
#ifndef deepdraw_discretisation_thickness_measurement_h
#define deepdraw_discretisation_thickness_measurement_h

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/blank/sheet_thickness.h>
#include <memory>
#include <vector>

namespace deepdraw
{
  namespace discretisation
  {
    using namespace dealii;

    class ThicknessMeasurement
    {
    public:
      // On the initial surfaces of the current mesh (D72); on a refined mesh
      // the refined faces, hanging vertices included (D85). Throws
      // InputError if a vertex does not lie over both the bottom and the
      // top face.
      void
      set_up(const Triangulation<3>      &mesh,
             const std::vector<Point<3>> &initial_vertices);
      // The thickness at every vertex of the mesh's current configuration;
      // nominal_thickness where no active cell uses a vertex.
      void
      update(const Triangulation<3> &mesh, double nominal_thickness);

      const blank::SheetThickness &
      sheet_thickness() const;
      const std::vector<double> &
      vertex_thickness() const;

    private:
      std::unique_ptr<blank::SheetThickness>       sheet;
      std::vector<blank::SheetThickness::Location> vertex_locations;
      std::vector<double>                          thickness;
    };
  } // namespace discretisation
} // namespace deepdraw

#endif
