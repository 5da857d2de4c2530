// What the closest-point projection of a point x onto a rigid tool returns:
// everything the contact law and its linearisation need, in global
// coordinates at the tool's current placement.
#ifndef deepdraw_geometry_projection_result_h
#define deepdraw_geometry_projection_result_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace deepdraw::geometry
{
  struct ProjectionResult
  {
    // g_N = (x - foot) · normal: positive on the normal side (open).
    double gap = 0.;
    // |x - foot|; equals |gap| unless the foot is clamped onto an edge.
    double distance = 0.;
    // Closest point on the tool, and the same material point in the tool's
    // own frame (for the tool's motion at that point).
    dealii::Point<3> foot;
    dealii::Point<3> foot_in_tool_frame;
    // Unit normal, pointing towards the sheet.
    dealii::Tensor<1, 3> normal;
    // dx/du, dx/dv at the foot.
    dealii::Tensor<1, 3> tangent_u, tangent_v;
    // d2x/du2, d2x/dudv, d2x/dv2 at the foot.
    dealii::Tensor<1, 3> x_uu, x_uv, x_vv;
    // a_ab = x_a · x_b and b_ab = x_ab · normal (index 0: u, 1: v).
    dealii::Tensor<2, 2> metric;
    dealii::Tensor<2, 2> second_fundamental_form;
    // dn/dx on the tangent plane, -b_ab a^a ⊗ a^b; its eigenvalues are the
    // principal curvatures, positive where the tool is convex towards the
    // sheet (punch nose, die shoulder: +1/radius).
    dealii::Tensor<2, 3>  curvature;
    std::array<double, 2> principal_curvatures = {{0., 0.}};
    // Patch parameters of the foot and index of the patch in the tool.
    double       u = 0., v = 0.;
    unsigned int patch = 0;
    // The foot is clamped onto a patch edge (x lies beyond it).
    bool on_edge = false;
    // The foot is clamped onto a free edge of the tool (an edge no other
    // patch continues, e.g. the blank holder's inner contour): x is beside
    // the tool, the contact code treats it as "not in contact".
    bool on_free_edge = false;
    // The foot lies outside the trimming loops of its patch's CAD face
    // (doc/tool_files.md, CAD tools); on_free_edge is then set too.
    bool outside_trimming = false;
  };
} // namespace deepdraw::geometry

#endif
