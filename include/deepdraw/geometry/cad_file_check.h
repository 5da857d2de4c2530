// The frame of a STEP or IGES file, checked before OpenCASCADE parses it
// (doc/tool_files.md, CAD tools: errors): a STEP file must begin with
// "ISO-10303-21;" and end with "END-ISO-10303-21;" (ISO 10303-21 §5); an
// IGES file (fixed ASCII form) has 80-column lines with the section letter
// S, G, D, P or T in column 73 and ends with the terminate section, which
// counts the lines of the others (IGES 5.3 §2.2.5). A file cut short fails
// here with a clear message; OpenCASCADE's IGES reader may crash on one.
// A STEP file may nest parentheses at most max_step_nesting deep (D165):
// OpenCASCADE's reader overflows its stack on deeper ones.
#ifndef deepdraw_geometry_cad_file_check_h
#define deepdraw_geometry_cad_file_check_h

#include <string>

namespace deepdraw::geometry
{
  constexpr unsigned int max_step_nesting = 100;

  // Throws InputError "<filename>: ..." if the frame is broken.
  void
  check_step_frame(const std::string &filename);

  void
  check_iges_frame(const std::string &filename);
} // namespace deepdraw::geometry

#endif
