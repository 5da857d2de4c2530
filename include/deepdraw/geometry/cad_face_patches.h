// One face of a CAD shape as exact rational Bézier patches, with its
// trimming loops (doc/tool_files.md, "CAD tools"; decisions D45, D46).
//
// The face's surface is bounded by the face's parameter range, converted
// exactly into a rational B-spline (GeomConvert::SurfaceToBSplineSurface:
// planes, cylinders, cones, spheres, tori, surfaces of revolution and of
// linear extrusion of lines, conics, Bézier and B-spline curves, Bézier
// and B-spline surfaces, offsets of elementary surfaces) and split at its
// knots into Bézier patches (GeomConvert_BSplineSurfaceToBezierSurface).
// Surfaces OCCT could only approximate are rejected.
//
// The trimming loops (the face's wires, through their pcurves) become
// polygons in the B-spline's parameter plane, fine enough that their image
// on the surface lies within `trimming_tolerance` of the true boundary
// (checked at the midpoint of every polygon edge, which is halved until it
// does). Patches entirely inside the loops are untrimmed, patches outside
// are dropped, the others carry the loops (PatchTrimming).
#ifndef deepdraw_geometry_cad_face_patches_h
#define deepdraw_geometry_cad_face_patches_h

#include <deal.II/base/point.h>
#include <deepdraw/geometry/bezier_patch.h>
#include <deepdraw/geometry/trimmed_domain.h>
#include <functional>
#include <string>
#include <vector>
// OpenCASCADE after deal.II (its macro Handle() breaks Sacado::Handle).
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

namespace deepdraw::geometry
{
  struct CadFacePatches
  {
    // Oriented as the surface (x_u × x_v is the surface's normal, before
    // the face's orientation flag).
    std::vector<BezierPatch>   patches;
    std::vector<PatchTrimming> trimmings;
    // Whether some patch is trimmed or dropped (the face is not the whole
    // parameter rectangle of its surface).
    bool         trimmed   = false;
    unsigned int n_dropped = 0;

    // The face's boundary, edge by edge: the topological edge, the polygon
    // of its pcurve in the B-spline's (U, V) and the points on the surface
    // it was sampled at.
    struct BoundaryEdge
    {
      TopoDS_Edge                   edge;
      std::vector<dealii::Point<2>> parameters;
      std::vector<dealii::Point<3>> points;
    };
    std::vector<BoundaryEdge> boundary;
  };

  // Throws InputError "<filename>: <face_label()>: ..." if the face's surface
  // is missing, cannot be converted exactly, or has a degree above
  // BezierPatch::max_degree.
  CadFacePatches
  convert_cad_face(const TopoDS_Face                  &face,
                   const std::function<std::string()> &face_label,
                   const std::string                  &filename,
                   double                              trimming_tolerance);

  // The patch reversed in s (normal flipped), its trimming map adjusted.
  void
  reverse_patch(BezierPatch &patch, PatchTrimming &trimming);
} // namespace deepdraw::geometry

#endif
