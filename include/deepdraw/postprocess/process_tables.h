// The forming-process tables (doc/user_guide.md §3), a component declared in
// `subsection Process tables`: which tool is the punch and which the blank
// holder (punch_force.csv), and where the draw-in of the blank edge is
// measured (draw_in.csv).
#ifndef deepdraw_postprocess_process_tables_h
#define deepdraw_postprocess_process_tables_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deepdraw/blank/blank_geometry.h>
#include <deepdraw/blank/sheet_thickness.h>
#include <deepdraw/contact/contact_coupling.h>
#include <deepdraw/io/csv_file.h>
#include <optional>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace postprocess
  {
    using namespace dealii;

    class ProcessTables
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      // Throws InputError naming the parameter on a malformed entry.
      void
      parse_parameters(ParameterHandler           &prm,
                       const blank::BlankGeometry &geometry);

      // After the tools and the mesh exist: finds the punch and the holder
      // (InputError if a tool named in the prm does not exist), the punch
      // direction over the run (to final_load), the points of the named
      // directions (x axis, y axis, diagonal: where the ray from the origin
      // leaves the sheet) and where each draw-in point lies on the sheet
      // (InputError if off it).
      void
      set_up(const contact::ContactCoupling &contact,
             double                          final_load,
             const blank::SheetThickness    &sheet,
             const std::vector<Point<3>>    &initial_vertices);

      // Unit direction of the punch motion (set_up; -z without a punch).
      const Tensor<1, 3> &
      punch_motion() const;

      // Opens the tables in directory (runs with tools only), appending to
      // them on a resumed run.
      void
      open(const std::string &directory, bool append = false);
      // One row of each table at the converged load; vertices: the
      // current positions.
      void
      write(double                          load,
            const contact::ContactCoupling &contact,
            const std::vector<Point<3>>    &vertices);

    private:
      struct DrawInPoint
      {
        std::string name;
        Point<2>    requested;
        // Set instead of requested: the direction of a ray from the origin
        // ("x axis", "y axis", "diagonal"), the point where it leaves the
        // sheet.
        std::optional<Tensor<1, 2>> ray;
        // Where it lies on the sheet, and the initial distance of its
        // mid-surface point from the cup axis x = y = 0.
        blank::SheetThickness::Location location;
        double                          initial_radius = 0.;
      };

      std::string              punch_name  = "punch";
      std::string              holder_name = "";
      std::vector<DrawInPoint> draw_in_points;

      bool         tables_wanted   = false;
      unsigned int punch_tool      = numbers::invalid_unsigned_int;
      unsigned int holder_tool     = numbers::invalid_unsigned_int;
      Tensor<1, 3> punch_direction = Tensor<1, 3>({0., 0., -1.});
      io::CsvFile  punch_force_file;
      io::CsvFile  draw_in_file;
    };
  } // namespace postprocess
} // namespace deepdraw

#endif
