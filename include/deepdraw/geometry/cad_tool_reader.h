// Rigid tools from STEP and IGES files through OpenCASCADE
// (doc/tool_files.md, "CAD tools"; decisions D45-D49).
//
// Every face becomes exact rational Bézier patches (CadFacePatches), so the
// projection and contact code work on CAD tools as on any other tool.
// Edges of a patch are free where they lie on a face edge that no other
// face shares (TopExp::MapShapesAndUniqueAncestors), symmetry edges where
// such an edge lies in a symmetry plane of the model, shared otherwise.
// Trimmed faces keep their loops: a foot outside them is not in contact.
// Normals are turned towards the sheet (CadNormals). Any failure is an
// InputError naming the file (and the face).
#ifndef deepdraw_geometry_cad_tool_reader_h
#define deepdraw_geometry_cad_tool_reader_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/tensor.h>
#include <deepdraw/geometry/rigid_tool.h>
#include <string>

namespace deepdraw::geometry
{
  enum class CadNormals
  {
    // The faces' normals as in the file (face orientation applied), then
    // every connected set of faces whose normals point away from the sheet
    // on average is reversed (D48).
    automatic,
    // As in the file: the outward normal of a solid, or the surface normal
    // with the face's orientation flag for a shell.
    as_in_file,
    // The file's normals, all reversed.
    reversed
  };

  struct CadToolOptions
  {
    // "file": the unit the file declares (OpenCASCADE converts it to mm);
    // "mm", "cm", "m", "inch": the file's numbers are in that unit, whatever
    // it declares.
    std::string length_unit = "file";
    CadNormals  normals     = CadNormals::automatic;
    // From the tool towards the sheet: (0, 0, -1) for a tool on the sheet's
    // top surface, (0, 0, 1) below it (CadNormals::automatic).
    dealii::Tensor<1, 3> towards_sheet = dealii::Tensor<1, 3>({0., 0., -1.});
    // Symmetry planes x = 0, y = 0 of the model: a face edge no other face
    // shares is a symmetry edge, not a free one, if it lies in one of them.
    bool symmetry_plane_x = false;
    bool symmetry_plane_y = false;
  };

  // What the reader found.
  struct CadToolReport
  {
    std::string  format; // "STEP" or "IGES"
    std::string  file_unit;
    double       scale           = 1.; // applied to OpenCASCADE's mm
    unsigned int n_faces         = 0;
    unsigned int n_patches       = 0;
    unsigned int n_trimmed_faces = 0;
    // Patches of trimmed faces that lie entirely outside the loops.
    unsigned int n_dropped_patches = 0;
    // Faces whose normal was reversed (relative to the file).
    unsigned int           n_reversed_faces = 0;
    unsigned int           n_free_edges     = 0; // patch edges
    dealii::BoundingBox<3> bounding_box;

    // One line: faces, patches, trimmed and reversed faces, unit, box.
    std::string
    summary() const;
  };

  // Reads filename (.step, .stp, .iges, .igs, any case) into a tool named
  // `name` placed at the identity. Throws InputError naming the file, and
  // the face for a face that cannot be converted.
  RigidTool
  read_cad_tool(const std::string    &filename,
                const std::string    &name,
                const CadToolOptions &options = CadToolOptions(),
                CadToolReport        *report  = nullptr);
} // namespace deepdraw::geometry

#endif
