// VTU output of a tool at its current placement, for ParaView: every patch
// triangulated on a (subdivisions × subdivisions) parameter grid, with the
// unit normal as point data and the patch index as cell data. Written
// through filename.tmp and a rename; throws io::OutputError if the file
// cannot be written or a point is not finite.
#ifndef deepdraw_geometry_tool_vtu_h
#define deepdraw_geometry_tool_vtu_h

#include <deepdraw/geometry/rigid_tool.h>
#include <string>

namespace deepdraw::geometry
{
  void
  write_vtu(const RigidTool   &tool,
            const std::string &filename,
            unsigned int       subdivisions);
} // namespace deepdraw::geometry

#endif
