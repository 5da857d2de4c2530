// Writes a rigid tool as a STEP or IGES file through OpenCASCADE
// (doc/tool_files.md, "CAD tools"): every Bézier patch becomes a face on a
// Geom_BezierSurface with its weights, bounded by its parameter square; the
// faces are sewn into a shell (adjacent patches then share their edges) and
// written in millimetres. Patch orientation is kept: a face's normal is the
// patch's x_u × x_v. Used to check the CAD reader against the exact builder
// (`deepdraw --write-square-cup-tools DIR`).
#ifndef deepdraw_geometry_cad_tool_writer_h
#define deepdraw_geometry_cad_tool_writer_h

#include <deepdraw/geometry/rigid_tool.h>
#include <string>
#include <vector>

namespace deepdraw::geometry
{
  // The format follows the extension: .step or .stp (STEP AP214), .iges or
  // .igs (IGES 5.3, B-rep mode: faces, shells and shared edges). `unit`:
  // the length unit declared in the file, as OpenCASCADE names it ("MM",
  // "M", "IN", ...); the tool's millimetres are converted to it. Throws
  // InputError naming the file if it cannot be written.
  void
  write_cad_tool(const RigidTool   &tool,
                 const std::string &filename,
                 const std::string &unit = "MM");

  // Writes every tool to directory/<name>.step and directory/<name>.iges
  // (spaces in the name become underscores; the directory is created) and
  // returns the file names.
  std::vector<std::string>
  write_cad_tool_files(const std::vector<RigidTool> &tools,
                       const std::string            &directory);
} // namespace deepdraw::geometry

#endif
