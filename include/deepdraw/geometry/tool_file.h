// Plain-text tool files (format: doc/tool_files.md). Reading checks every
// line and throws deepdraw::InputError "file:line: what is wrong" on the
// first error; writing uses max_digits10 so that write → read is exact and
// throws io::OutputError if the file cannot be written.
#ifndef deepdraw_geometry_tool_file_h
#define deepdraw_geometry_tool_file_h

#include <deepdraw/geometry/rigid_tool.h>
#include <string>
#include <vector>

namespace deepdraw::geometry
{
  // The tool is placed at the identity (its frame is the global frame).
  RigidTool
  read_tool_file(const std::string &filename);

  void
  write_tool_file(const RigidTool &tool, const std::string &filename);

  // Writes every tool to directory/<name>.tool (spaces in the name become
  // underscores; the directory is created) and returns the file names.
  std::vector<std::string>
  write_tool_files(const std::vector<RigidTool> &tools,
                   const std::string            &directory);
} // namespace deepdraw::geometry

#endif
