// The in-plane surface strains of every column of the sheet
// (doc/theory_formability.md §1.1): a column is a stack of active cells that
// share their in-plane footprint, joined across their through-thickness
// faces (4 and 5, as extruded from the blank), stacks over the same
// footprint being one column and a stack that ends at a refined face
// belonging to the finer columns of its footprint (D173); its centre (X, Y) in
// the initial configuration is located on the sheet's bottom and top surfaces
// (blank::SheetThickness), and the principal logarithmic strains since
// t = 0 are those of the bottom surface, of the top surface and of the mid
// surface x = (x_top + x_bottom)/2 there (formability::surface_strain), in
// their current tangent planes: no coordinate plane is assumed (the sheet
// turns into the cup wall). Exact for homogeneous deformations, on any
// hexahedral sheet mesh, refined or not.
#ifndef deepdraw_postprocess_column_strains_h
#define deepdraw_postprocess_column_strains_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/blank/sheet_thickness.h>
#include <deepdraw/formability/surface_strain.h>
#include <map>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace postprocess
  {
    using namespace dealii;

    // The surfaces of a column; the values are those of the `surface`
    // column of formability.csv and fld_<travel>mm.csv.
    enum class SheetSurface : unsigned int
    {
      bottom = 0,
      mid    = 1,
      top    = 2
    };
    constexpr std::array<SheetSurface, 3> sheet_surfaces
      = {{SheetSurface::bottom, SheetSurface::mid, SheetSurface::top}};

    // "bottom", "mid", "top".
    std::string
    surface_name(SheetSurface surface);

    // The strains of one column.
    struct ColumnStrain
    {
      // By SheetSurface.
      std::array<formability::SurfaceStrain, 3> surfaces;
      // ln(t/t0) at the column's centre (blank::SheetThickness).
      double thickness_strain = 0.;
    };

    class ColumnStrains
    {
    public:
      // The columns of the active cells of mesh, their centres in
      // initial_vertices (the configuration at t = 0, indexed like the
      // mesh's vertices) and where those lie on the bottom and top surfaces
      // of `surfaces` (set up on the same mesh and configuration). Throws
      // InputError if a centre lies over no surface face.
      void
      set_up(const Triangulation<3>      &mesh,
             const std::vector<Point<3>> &initial_vertices,
             const blank::SheetThickness &surfaces);

      unsigned int
      n_columns() const;
      // The column of every active cell, by active cell index.
      const std::vector<unsigned int> &
      column_of_cell() const;
      // The centre (X, Y) of a column at t = 0.
      const Point<2> &
      centre(unsigned int column) const;
      // After a mesh change (refinement): for each column, the column of
      // `previous` (set up on the mesh before the change) that held its
      // lowest cell or that cell's nearest ancestor;
      // numbers::invalid_unsigned_int where there is none.
      std::vector<unsigned int>
      inherited_from(const ColumnStrains &previous) const;

      // The strains of every column in the configuration `vertices`;
      // `surfaces` must have been updated on them (SheetThickness::update)
      // for the thickness strain, whose initial value is
      // initial_thickness.
      std::vector<ColumnStrain>
      compute(const std::vector<Point<3>> &vertices,
              const blank::SheetThickness &surfaces,
              double                       initial_thickness) const;

    private:
      // A point of the bottom or top surface: its face's vertices, its
      // reference coordinates there, and d(xi, eta)/d(X, Y) (the inverse
      // of the face's in-plane Jacobian at t = 0).
      struct SurfacePoint
      {
        std::array<unsigned int, 4> vertices{};
        double                      xi = 0., eta = 0.;
        Tensor<2, 2>                inverse_jacobian;
        // d x / d X, d x / d Y at t = 0.
        std::array<Tensor<1, 3>, 2> initial_tangents;

        SurfacePoint() = default;
        SurfacePoint(const std::array<unsigned int, 4> &vertices,
                     const std::array<double, 4>       &weights,
                     const std::vector<Point<3>>       &initial_vertices);

        // d x / d X, d x / d Y in the configuration `vertices`.
        std::array<Tensor<1, 3>, 2>
        tangents(const std::vector<Point<3>> &vertices) const;
      };

      struct Column
      {
        Point<2>                        centre;
        blank::SheetThickness::Location location;
        SurfacePoint                    bottom, top;
      };

      using Cell = Triangulation<3>::active_cell_iterator;

      // The column of the stack whose lowest cell is bottom: its centre
      // located on the surfaces (InputError if it lies over none).
      static Column
      make_column(const Cell                  &bottom,
                  const std::vector<Point<3>> &initial_vertices,
                  const blank::SheetThickness &surfaces);
      // The cells of stack belong to column.
      void
      assign(const std::vector<Cell> &stack, unsigned int column);

      std::vector<Column>       columns;
      std::vector<unsigned int> cell_column;
      // The lowest cell of each column, and the column of every cell by
      // its id (which outlives a refinement).
      std::vector<Triangulation<3>::active_cell_iterator> lowest;
      std::map<CellId, unsigned int>                      column_of_id;
    };
  } // namespace postprocess
} // namespace deepdraw

#endif
