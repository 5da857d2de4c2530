// Length units of CAD tools (doc/tool_files.md, CAD tools: units): the
// square-cup punch written in millimetres, in metres (STEP) and in inches
// (IGES). With Length unit = file every version gives the punch in mm (the
// declared unit converted by OpenCASCADE); an explicit unit takes the
// file's numbers in that unit, whatever the file declares.
#include "test_utilities.h"

#include <deepdraw/geometry/cad_tool_reader.h>
#include <deepdraw/geometry/cad_tool_writer.h>
#include <deepdraw/geometry/square_cup_tools.h>
#include <filesystem>
#include <unistd.h>

using namespace deepdraw::geometry;
using namespace deepdraw_test;
using dealii::Point;

namespace
{
  const std::filesystem::path directory
    = std::filesystem::temp_directory_path()
      / ("deepdraw_cad_length_units_" + std::to_string(::getpid()));

  // Largest corner of the tool's box.
  Point<3>
  upper_corner(const std::string &filename,
               const std::string &unit,
               CadToolReport     &report)
  {
    CadToolOptions options;
    options.length_unit  = unit;
    const RigidTool tool = read_cad_tool(filename, "punch", options, &report);
    std::cout << "  " << filename << ", Length unit = " << unit << ": "
              << report.summary() << std::endl;
    return tool.bounding_box().get_boundary_points().second;
  }

  void
  check_scale(const std::string &filename,
              const std::string &unit,
              const double       factor,
              const Point<3>    &reference)
  {
    CadToolReport  report;
    const Point<3> corner = upper_corner(filename, unit, report);
    double         error  = 0.;
    for (unsigned int d = 0; d < 3; ++d)
      error = std::max(error, std::abs(corner[d] - factor * reference[d]));
    check_close(filename + " read as " + unit + ": box corner = "
                  + std::to_string(factor) + " x the punch's in mm",
                error,
                0.,
                1e-9 * factor * reference.norm());
  }
} // namespace


int
main()
{
  std::filesystem::create_directories(directory);
  const RigidTool punch
    = build_square_cup_tools(SquareCupToolParameters(), 0.81)[0];
  const Point<3> reference  = punch.bounding_box().get_boundary_points().second;
  const std::string mm_step = (directory / "punch_mm.step").string();
  const std::string m_step  = (directory / "punch_m.step").string();
  const std::string in_iges = (directory / "punch_inch.iges").string();
  write_cad_tool(punch, mm_step);
  // OpenCASCADE converts the tool's millimetres into the declared unit.
  write_cad_tool(punch, m_step, "M");
  write_cad_tool(punch, in_iges, "IN");

  // Declared units, converted.
  check_scale(mm_step, "file", 1., reference);
  check_scale(m_step, "file", 1., reference);
  check_scale(in_iges, "file", 1., reference);
  // Replaced units: the numbers taken in the given unit.
  check_scale(mm_step, "mm", 1., reference);
  check_scale(mm_step, "cm", 10., reference);
  check_scale(mm_step, "m", 1000., reference);
  check_scale(mm_step, "inch", 25.4, reference);
  check_scale(m_step, "m", 1., reference);
  check_scale(m_step, "mm", 1e-3, reference);
  check_scale(in_iges, "inch", 1., reference);
  check_scale(in_iges, "mm", 1. / 25.4, reference);

  if (!std::getenv("DEEPDRAW_KEEP_FILES"))
    std::filesystem::remove_all(directory);
  return summary();
}
