// Trimmed CAD faces (doc/tool_files.md, CAD tools: trimming):
// - a planar square face 100 x 100 mm with a circular hole of radius 20,
//   as STEP and as IGES: points over the hole are open (outside the
//   trimming loops), points over the face are in contact with the exact
//   gap and foot, points beyond the square's sides lie beyond a free edge;
//   the hole's edge is found to within the trimming tolerance (1e-6 of the
//   tool size); with the sheet on the other side the face is reversed;
//   the tool's VTU leaves the hole out;
// - a face on a cylinder (radius 30) bounded by a diamond in (angle, z),
//   whose sides are no iso-lines, so that the loops come from points on
//   the surface mapped into the rational B-spline's parameters (whose
//   parameter is not the angle): inside the diamond in contact with gap =
//   distance to the axis - 30, outside it open.
#include "test_utilities.h"

// deal.II first: OpenCASCADE's macro Handle() breaks Trilinos' Sacado::Handle,
// which deal.II's headers declare.
#include <deal.II/base/config.h>
// OpenCASCADE:
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepLib.hxx>
#include <GCE2d_MakeSegment.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <cmath>
#include <deepdraw/geometry/cad_occt_messages.h>
#include <deepdraw/geometry/cad_tool_reader.h>
#include <deepdraw/geometry/tool_vtu.h>
#include <filesystem>
#include <fstream>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>
#include <random>
#include <unistd.h>

using namespace deepdraw::geometry;
using namespace deepdraw_test;
using dealii::Point;
using Vector = dealii::Tensor<1, 3>;

namespace
{
  const std::filesystem::path directory
    = std::filesystem::temp_directory_path()
      / ("deepdraw_cad_trimmed_faces_" + std::to_string(::getpid()));

  void
  write(const TopoDS_Shape &shape, const std::string &filename)
  {
    const MutedOcctMessages muted;
    if (filename.find(".step") != std::string::npos)
    {
      STEPControl_Writer writer;
      writer.Transfer(shape, STEPControl_AsIs);
      writer.Write(filename.c_str());
    }
    else
    {
      IGESControl_Controller::Init();
      IGESControl_Writer writer("MM", 1);
      writer.AddShape(shape);
      writer.ComputeModel();
      writer.Write(filename.c_str());
    }
  }

  TopoDS_Face
  plate_with_hole()
  {
    BRepBuilderAPI_MakePolygon square(gp_Pnt(-50, -50, 0),
                                      gp_Pnt(50, -50, 0),
                                      gp_Pnt(50, 50, 0),
                                      gp_Pnt(-50, 50, 0),
                                      Standard_True);
    BRepBuilderAPI_MakeFace    face(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)),
                                 square.Wire());
    const TopoDS_Wire hole = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(
      gp_Circ(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 20.)));
    face.Add(TopoDS::Wire(hole.Reversed()));
    return face.Face();
  }

  // The diamond |angle - pi/4| / 0.5 + |z| / 10 <= 1 on the cylinder of
  // radius 30 around the z axis.
  TopoDS_Face
  diamond_on_cylinder()
  {
    const Handle(Geom_CylindricalSurface) cylinder
      = new Geom_CylindricalSurface(gp_Ax3(gp::XOY()), 30.);
    const double            c          = M_PI / 4;
    const gp_Pnt2d          corners[4] = {gp_Pnt2d(c - 0.5, 0.),
                                          gp_Pnt2d(c, -10.),
                                          gp_Pnt2d(c + 0.5, 0.),
                                          gp_Pnt2d(c, 10.)};
    BRepBuilderAPI_MakeWire wire;
    for (unsigned int k = 0; k < 4; ++k)
      wire.Add(BRepBuilderAPI_MakeEdge(
        GCE2d_MakeSegment(corners[k], corners[(k + 1) % 4]).Value(),
        cylinder));
    TopoDS_Face face = BRepBuilderAPI_MakeFace(cylinder, wire.Wire()).Face();
    BRepLib::BuildCurves3d(face);
    return face;
  }

  void
  check_plate(const std::string &filename)
  {
    write(plate_with_hole(), filename);
    CadToolOptions options;
    options.towards_sheet = Vector({0., 0., 1.});
    CadToolReport   report;
    const RigidTool tool = read_cad_tool(filename, "plate", options, &report);
    std::cout << filename << ": " << report.summary() << std::endl;
    check_true(filename + ": one trimmed face", report.n_trimmed_faces == 1);
    if (tool.trimming(0).trimmed())
    {
      std::cout << "  trimming polygons:";
      for (const auto &loop : tool.trimming(0).domain->loops())
        std::cout << " " << loop.size();
      std::cout << " vertices, tolerance "
                << tool.trimming(0).domain->tolerance() << " mm" << std::endl;
    }

    std::mt19937                           random(7);
    std::uniform_real_distribution<double> unit(0., 1.);
    unsigned int n_hole = 0, n_face = 0, n_beyond = 0, wrong = 0;
    double       gap_error = 0., foot_error = 0.;
    for (unsigned int n = 0; n < 4000; ++n)
    {
      const Point<3> x(-60 + 120 * unit(random),
                       -60 + 120 * unit(random),
                       -0.5 + 2 * unit(random));
      const double   r = std::hypot(x[0], x[1]);
      // Leave out a band of 1e-3 mm around the circle (its polygon is
      // within the trimming tolerance, 1.4e-4 mm here).
      if (std::abs(r - 20.) < 1e-3)
        continue;
      ProjectionResult result;
      const bool       found = tool.project(x, result, 5.);
      if (r < 20.)
      {
        ++n_hole;
        wrong += found && !(result.on_free_edge && result.outside_trimming);
      }
      else if (std::max(std::abs(x[0]), std::abs(x[1])) > 50.)
      {
        ++n_beyond;
        wrong += found && !(result.on_free_edge && !result.outside_trimming);
      }
      else
      {
        ++n_face;
        wrong += !found || result.on_free_edge;
        gap_error  = std::max(gap_error, std::abs(result.gap - x[2]));
        foot_error = std::max(foot_error,
                              result.foot.distance(Point<3>(x[0], x[1], 0.)));
      }
    }
    std::cout << "  " << n_hole << " points over the hole, " << n_face
              << " over the face, " << n_beyond << " beyond its sides"
              << std::endl;
    check_true(filename
                 + ": open over the hole, in contact over the face, "
                   "free beyond the sides",
               wrong == 0);
    check_close(filename + ": gap over the face (mm)", gap_error, 0., 1e-12);
    check_close(filename + ": foot over the face (mm)", foot_error, 0., 1e-12);

    // The hole's edge along a ray at 30 degrees, and the trimming tolerance.
    const double tolerance = 1e-6 * std::sqrt(2 * 100. * 100.);
    for (const double radius :
         {20. - 1e-3, 20. - 3 * tolerance, 20. - 0.5 * tolerance, 20. + 1e-3})
    {
      ProjectionResult result;
      const Point<3>   x(radius * std::cos(M_PI / 6),
                       radius * std::sin(M_PI / 6),
                       0.3);
      tool.project(x, result, 5.);
      const bool expected_outside = radius < 20. - tolerance;
      check_true(filename + ": r = " + std::to_string(radius) + ": "
                   + (expected_outside ? "open" : "in contact"),
                 result.outside_trimming == expected_outside
                   && result.on_free_edge == expected_outside);
    }

    // The VTU of the tool leaves the hole out: of the 2 x 40 x 40
    // triangles of the plate's patch, those whose square's centre lies in
    // the hole (area fraction pi 20^2 / 100^2 = 12.6 %) are not written.
    const std::string vtu = filename + ".vtu";
    write_vtu(tool, vtu, 40);
    std::ifstream      in(vtu);
    const std::string  text((std::istreambuf_iterator<char>(in)),
                           std::istreambuf_iterator<char>());
    const auto         at = text.find("NumberOfCells=\"");
    const unsigned int n_cells
      = at == std::string::npos ? 0 : std::stoul(text.substr(at + 15));
    std::cout << "  VTU: " << n_cells << " of 3200 triangles" << std::endl;
    check_true(filename
                 + ": the VTU leaves the hole out (12.6 % of 3200 "
                   "triangles)",
               std::abs(n_cells / 3200. - (1. - M_PI * 0.04)) < 0.01);

    // Sheet below: the face is reversed, the gap changes sign.
    options.towards_sheet = Vector({0., 0., -1.});
    const RigidTool reversed
      = read_cad_tool(filename, "plate", options, &report);
    ProjectionResult result;
    reversed.project(Point<3>(30., 30., -0.25), result, 5.);
    check_true(filename + ": sheet below: one face reversed",
               report.n_reversed_faces == 1);
    check_close(filename + ": sheet below: gap 0.25 below the plate",
                result.gap,
                0.25,
                1e-12);
  }

  void
  check_cylinder(const std::string &filename)
  {
    write(diamond_on_cylinder(), filename);
    CadToolOptions options;
    options.normals = CadNormals::as_in_file;
    CadToolReport   report;
    const RigidTool tool
      = read_cad_tool(filename, "cylinder", options, &report);
    std::cout << filename << ": " << report.summary() << std::endl;
    check_true(filename + ": one trimmed face", report.n_trimmed_faces == 1);

    std::mt19937                           random(11);
    std::uniform_real_distribution<double> unit(0., 1.);
    unsigned int n_inside = 0, n_outside = 0, wrong = 0;
    double       gap_error = 0.;
    for (unsigned int n = 0; n < 4000; ++n)
    {
      const double angle = M_PI / 4 - 0.5 + unit(random);
      const double z     = -10. + 20. * unit(random);
      const double h     = -0.5 + 1.5 * unit(random);
      const double measure
        = std::abs(angle - M_PI / 4) / 0.5 + std::abs(z) / 10.;
      if (std::abs(measure - 1.) < 1e-4)
        continue;
      const Point<3>   x((30. + h) * std::cos(angle),
                       (30. + h) * std::sin(angle),
                       z);
      ProjectionResult result;
      const bool       found = tool.project(x, result, 5.);
      if (measure < 1.)
      {
        ++n_inside;
        wrong += !found || result.on_free_edge;
        gap_error = std::max(gap_error, std::abs(result.gap - h));
      }
      else
      {
        ++n_outside;
        wrong += found && !result.on_free_edge;
      }
    }
    std::cout << "  " << n_inside << " points inside the diamond, " << n_outside
              << " outside" << std::endl;
    check_true(filename + ": in contact inside the diamond, open outside",
               wrong == 0);
    check_close(filename + ": gap inside (mm)", gap_error, 0., 1e-10);
  }
} // namespace


int
main()
{
  std::filesystem::create_directories(directory);
  check_plate((directory / "plate_with_hole.step").string());
  check_plate((directory / "plate_with_hole.iges").string());
  check_cylinder((directory / "diamond_on_cylinder.step").string());
  std::filesystem::remove_all(directory);
  return summary();
}
