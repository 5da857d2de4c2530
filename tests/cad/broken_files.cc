// Broken CAD files: an InputError naming the file and what is wrong (the
// face for a face that cannot be converted) from read_cad_tool, and, run
// through the deepdraw executable (path in the environment variable
// DEEPDRAW, set by tests/CMakeLists.txt), exit code 2 with that message and
// no output directory. The files are made here: empty, text, cut short at
// 20 places, unknown extension, missing, with surfaces of an unknown
// entity type, and STEP files with a face on an offset
// B-spline surface (OpenCASCADE could only approximate it) and a face of
// degree 16 (above BezierPatch::max_degree); through the executable also an
// IGES file with a damaged entity type, on which OpenCASCADE crashes.
#include "test_utilities.h"

// deal.II first: OpenCASCADE's macro Handle() breaks Trilinos' Sacado::Handle,
// which deal.II's headers declare.
#include <deal.II/base/config.h>
// OpenCASCADE:
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Builder.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Writer.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS_Compound.hxx>
#include <cstdio>
#include <deepdraw/geometry/cad_occt_messages.h>
#include <deepdraw/geometry/cad_tool_reader.h>
#include <deepdraw/geometry/cad_tool_writer.h>
#include <deepdraw/geometry/square_cup_tools.h>
#include <deepdraw/io/input_error.h>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

using namespace deepdraw::geometry;
using namespace deepdraw_test;

namespace
{
  const std::filesystem::path directory
    = std::filesystem::temp_directory_path()
      / ("deepdraw_cad_broken_files_" + std::to_string(::getpid()));

  std::string
  path(const std::string &name)
  {
    return (directory / name).string();
  }

  void
  write_text(const std::string &name, const std::string &content)
  {
    std::ofstream(path(name)) << content;
  }

  std::string
  read_text(const std::string &name)
  {
    std::ifstream in(path(name));
    return std::string((std::istreambuf_iterator<char>(in)),
                       std::istreambuf_iterator<char>());
  }

  // The first `fraction` of a file.
  void
  write_cut(const std::string &from,
            const std::string &name,
            const double       fraction = 0.5)
  {
    const std::string content = read_text(from);
    std::ofstream(path(name)) << content.substr(0, fraction * content.size());
  }

  // The file with every `text` replaced by `replacement`.
  void
  write_replaced(const std::string &from,
                 const std::string &name,
                 const std::string &text,
                 const std::string &replacement)
  {
    std::string content = read_text(from);
    for (auto at = content.find(text); at != std::string::npos;
         at      = content.find(text, at + replacement.size()))
      content.replace(at, text.size(), replacement);
    std::ofstream(path(name)) << content;
  }

  // A flat unit square and a second face on `surface`, as one STEP file.
  void
  write_step_with(const Handle(Geom_Surface) & surface, const std::string &name)
  {
    TColgp_Array2OfPnt poles(1, 2, 1, 2);
    poles(1, 1) = gp_Pnt(-1, 0, 0);
    poles(2, 1) = gp_Pnt(0, 0, 0);
    poles(1, 2) = gp_Pnt(-1, 1, 0);
    poles(2, 2) = gp_Pnt(0, 1, 0);
    BRep_Builder    builder;
    TopoDS_Compound compound;
    builder.MakeCompound(compound);
    builder.Add(
      compound,
      BRepBuilderAPI_MakeFace(new Geom_BezierSurface(poles), 1e-7).Face());
    builder.Add(compound, BRepBuilderAPI_MakeFace(surface, 1e-7).Face());
    const MutedOcctMessages muted;
    STEPControl_Writer      writer;
    writer.Transfer(compound, STEPControl_AsIs);
    writer.Write(path(name).c_str());
  }

  // A gently curved square over [0, 1]^2 of degree `degree` in u.
  Handle(Geom_BezierSurface) curved_square(const int degree)
  {
    TColgp_Array2OfPnt poles(1, degree + 1, 1, 2);
    for (int i = 0; i <= degree; ++i)
      for (int j = 0; j <= 1; ++j)
        poles(i + 1, j + 1) = gp_Pnt(double(i) / degree, j, 0.1 * (i % 2));
    return new Geom_BezierSurface(poles);
  }

  std::string
  read_error(const std::string &name)
  {
    try
    {
      read_cad_tool(path(name), "tool");
    }
    catch (const deepdraw::InputError &error)
    {
      return error.what();
    }
    return "(no error)";
  }

  bool
  contains_all(const std::string &text, const std::vector<std::string> &pieces)
  {
    for (const std::string &piece : pieces)
      if (text.find(piece) == std::string::npos)
        return false;
    return true;
  }

  void
  expect_error(const std::string &name, const std::vector<std::string> &pieces)
  {
    const std::string message = read_error(name);
    std::cout << "  " << name << " -> " << message << std::endl;
    std::vector<std::string> with_file = pieces;
    with_file.push_back(path(name));
    check_true(name + ": the message names the file and says why",
               contains_all(message, with_file));
  }

  // deepdraw on a prm whose punch is `name`: exit code 2, the message, no
  // output directory.
  void
  expect_exit_code_2(const std::string              &name,
                     const std::vector<std::string> &pieces)
  {
    const char *deepdraw = std::getenv("DEEPDRAW");
    if (!deepdraw)
    {
      check_true("DEEPDRAW (the executable) is set", false);
      return;
    }
    const std::string prm    = path(name + ".prm");
    const std::string output = path(name + ".output");
    write_text(name + ".prm",
               "subsection Contact\n"
               "  subsection Tool 1\n"
               "    set Name     = punch\n"
               "    set Geometry = cad\n"
               "    set File     = "
                 + path(name)
                 + "\n"
                   "  end\n"
                   "end\n");
    const std::string command = std::string(deepdraw) + " " + prm
                                + " --output-directory " + output + " 2>&1";
    FILE       *pipe = popen(command.c_str(), "r");
    std::string text;
    char        buffer[512];
    while (pipe && fgets(buffer, sizeof(buffer), pipe))
      text += buffer;
    const int status = pipe ? pclose(pipe) : -1;
    const int code   = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::cout << "  deepdraw on " << name << ": exit code " << code << ": "
              << text;
    std::vector<std::string> with_file = pieces;
    with_file.push_back(path(name));
    check_true(name + ": exit code 2", code == 2);
    check_true(name + ": the message names the file and says why",
               contains_all(text, with_file));
    check_true(name + ": nothing written", !std::filesystem::exists(output));
  }
} // namespace


int
main()
{
  std::filesystem::create_directories(directory);
  const std::vector<RigidTool> tools
    = build_square_cup_tools(SquareCupToolParameters(), 0.81);
  write_cad_tool(tools[0], path("punch.step"));
  write_cad_tool(tools[0], path("punch.iges"));

  write_text("empty.step", "");
  write_text("text.step", "This is not a STEP file.\n");
  write_text("text.igs", "This is not an IGES file either.\n");
  write_cut("punch.step", "cut.step");
  write_cut("punch.iges", "cut.iges");
  std::filesystem::copy(path("punch.step"), path("punch.txt"));
  const Handle(Geom_BSplineSurface) bspline
    = GeomConvert::SurfaceToBSplineSurface(curved_square(3));
  write_step_with(new Geom_OffsetSurface(bspline, 0.5), "offset_face.step");
  write_step_with(curved_square(16), "degree_16.step");

  // STEP whose surfaces are of an unknown type: no face has a surface.
  write_replaced("punch.step",
                 "unknown_surfaces.step",
                 "B_SPLINE_SURFACE_WITH_KNOTS",
                 "B_SPLINE_SURFACE_WITH_KNOBS");

  expect_error("empty.step", {"empty"});
  expect_error("text.step", {"not a STEP file"});
  expect_error("text.igs", {"not an IGES file"});
  expect_error("cut.step", {"STEP file is incomplete"});
  expect_error("cut.iges", {"IGES file is incomplete"});
  // Cut anywhere (OpenCASCADE's IGES reader crashes on some of these; the
  // frame check stops them before).
  for (unsigned int k = 1; k < 20; ++k)
  {
    const std::string step = "cut_" + std::to_string(k) + ".step";
    const std::string iges = "cut_" + std::to_string(k) + ".iges";
    write_cut("punch.step", step, k / 20.);
    write_cut("punch.iges", iges, k / 20.);
    expect_error(step, {"STEP file is incomplete"});
    expect_error(iges, {"IGES file is incomplete"});
  }
  expect_error("unknown_surfaces.step", {"no faces"});
  expect_error("punch.txt", {"unknown CAD file extension"});
  expect_error("missing.step", {"cannot open"});
  expect_error("offset_face.step",
               {"face 2", "offset surface", "no exact rational form"});
  expect_error("degree_16.step",
               {"face 2", "degrees 16 x 1 above the maximum 15"});

  // The first rational B-spline curve (entity type 126) of the parameter
  // section with its type damaged, the frame intact: OpenCASCADE 7.6's
  // reader crashes on it, which deepdraw reports as an input error.
  {
    std::string content = read_text("punch.iges");
    const auto  at      = content.find("\n126,");
    if (at != std::string::npos)
      content[at + 1] = ')';
    std::ofstream(path("damaged.iges")) << content;
  }
  expect_exit_code_2("damaged.iges", {});

  expect_exit_code_2("empty.step", {"empty"});
  expect_exit_code_2("text.step", {"not a STEP file"});
  expect_exit_code_2("cut.step", {"STEP file is incomplete"});
  expect_exit_code_2("cut.iges", {"IGES file is incomplete"});
  expect_exit_code_2("offset_face.step", {"face 2", "offset surface"});

  if (!std::getenv("DEEPDRAW_KEEP_FILES"))
    std::filesystem::remove_all(directory);
  return summary();
}
