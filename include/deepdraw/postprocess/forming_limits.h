// Post-processor "forming limits" (doc/user_guide.md §8.2,
// doc/theory_formability.md §6): will the part split? For every column of
// the sheet and its bottom, mid and top surface: the major and minor
// logarithmic strains since t = 0 (ColumnStrains), the margin to the
// forming-limit curve of subsection Formability along the major strain, the
// zone of the forming-limit diagram, and the strain path. Writes
// formability.csv (a row per converged increment), flc.csv/.png and
// fld_<travel>mm.csv/.png at Formability/FLD travels, and the summary line
// of the run; the VTU fields major strain, minor strain, flc margin and fld
// zone read it (vtu_fields_formability.cc). The class is in a header for
// those fields (SimulationAccess::find_postprocessor, D141).
#ifndef deepdraw_postprocess_forming_limits_h
#define deepdraw_postprocess_forming_limits_h

#include <array>
#include <deepdraw/formability/formability_parameters.h>
#include <deepdraw/formability/strain_path.h>
#include <deepdraw/io/csv_file.h>
#include <deepdraw/postprocess/column_strains.h>
#include <deepdraw/postprocess/interface.h>
#include <memory>

namespace deepdraw
{
  namespace postprocess
  {
    class FormingLimits : public Interface
    {
    public:
      // Its name in Postprocess/List of postprocessors.
      static const std::string name;

      // A point of the forming-limit diagram.
      struct FldPoint
      {
        double                 major_strain = 0., minor_strain = 0.;
        formability::FlcMargin margin;
        formability::FldZone   zone = formability::FldZone::safe;
        // eps2 outside the curve's range, where a table is only held at its
        // end value (D131, D172): the margin is not measured there.
        bool beyond_range = false;
      };

      // A column's points by SheetSurface, and its thickness strain.
      struct ColumnFld
      {
        std::array<FldPoint, 3> surfaces;
        double                  thickness_strain = 0.;
      };

      // A point of the sheet and when it was seen: the worst point of an
      // increment, the first crossing of the curve, the least margin of
      // the run.
      struct Extreme
      {
        bool   found = false;
        double load  = 0.;
        // The column (on the mesh it was found on) and its centre at t = 0.
        unsigned int column = 0;
        Point<2>     centre;
        SheetSurface surface = SheetSurface::mid;
        FldPoint     point;
      };

      // Subsection Formability (FormabilityParameters) and its FLD travels.
      static void
      declare_parameters(ParameterHandler &prm);

      // InputError for Forming limit curve = none, or a curve that cannot
      // be read, naming the parameter.
      void
      parse_parameters(ParameterHandler &prm) override;

      // The curve (once: Keeler-Brazier's n and t default to Material/Swift
      // exponent and Geometry/Thickness, D133) and the columns of the
      // current mesh, their strain paths carried over from the columns they
      // were refined from.
      void
      initialize(const SimulationAccess &simulation) override;

      // The FLD travels up to the final load.
      std::vector<double>
      requested_loads(const SimulationAccess &simulation) const override;

      void
      start(const SimulationAccess &simulation, bool resume) override;

      void
      execute(const SimulationAccess &simulation) override;

      void
      save(std::ostream &stream) const override;
      void
      load(std::istream &stream) override;

      // Where the curve was first crossed, or the least margin; a point
      // beyond the curve's range is said to be, with the first crossing
      // (or the least margin) within the range (D172).
      std::string
      summary() const override;

      // Every column's points in the configuration of the last converged
      // increment (a function of the state only: the VTU fields call it
      // whatever the order of the post-processors).
      std::vector<ColumnFld>
      evaluate(const SimulationAccess &simulation) const;
      const ColumnStrains &
      columns() const;

    private:
      // The worst point (least margin along the major strain) of results,
      // of all points or of those within the curve's range, and the columns
      // per zone (a column counts in the first zone of classify()'s order
      // that one of its surfaces is in).
      Extreme
      worst_point(const std::vector<ColumnFld> &results,
                  double                        load,
                  bool                          within_range_only) const;
      std::array<unsigned int, 6>
      zone_counts(const std::vector<ColumnFld> &results) const;
      // The first crossing and the least margin updated by an increment's
      // worst point.
      void
      record(const Extreme &worst, Extreme &crossing, Extreme &least) const;
      // fld_<travel>mm.csv, .gp and .png.
      void
      write_fld_files(const SimulationAccess       &simulation,
                      const std::vector<ColumnFld> &results,
                      double                        travel) const;

      formability::FormabilityParameters              parameters;
      std::vector<double>                             travels;
      std::unique_ptr<formability::FormingLimitCurve> curve;
      ColumnStrains                                   column_strains;
      // By column and surface (3 k + surface).
      std::vector<formability::StrainPath> paths;
      Extreme                              first_crossing, least_margin;
      // The same among the points within the curve's range (D172).
      Extreme     first_crossing_in_range, least_margin_in_range;
      io::CsvFile table;
    };
  } // namespace postprocess
} // namespace deepdraw

#endif
