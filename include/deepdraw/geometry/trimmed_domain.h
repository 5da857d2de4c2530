// Trimming of a patch by the loops of the CAD face it comes from
// (doc/tool_files.md, "CAD tools: trimming"): a foot point outside the
// face's trimming loops is not in contact with that face, the same rule as
// a foot clamped onto a free edge (doc/theory_contact.md §3.2).
//
// The loops are closed polygons in the parameter plane (U, V) of the face's
// B-spline surface; each Bézier patch of the face covers one knot span
// [U0, U0 + dU] x [V0, V0 + dV] of it and maps its own (s, t) in [0, 1]^2
// affinely onto that span (dU < 0 for a patch reversed in s).
#ifndef deepdraw_geometry_trimmed_domain_h
#define deepdraw_geometry_trimmed_domain_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <memory>
#include <vector>

namespace deepdraw::geometry
{
  // The part of a parameter plane inside a set of closed polygons, by the
  // even-odd rule: inside the outer loop and outside every hole.
  class TrimmedDomain
  {
  public:
    // Each loop lists its vertices once; the last one connects to the first.
    // `tolerance`: how far (a length on the surface) the polygons may lie
    // from the true loops; points that close to a polygon count as inside.
    TrimmedDomain(const std::vector<std::vector<dealii::Point<2>>> &loops,
                  double                                            tolerance);

    const std::vector<std::vector<dealii::Point<2>>> &
    loops() const;
    double
    tolerance() const;

    // Crossing number of a ray from x towards +U, modulo 2.
    bool
    contains(const dealii::Point<2> &x) const;

    // Shortest distance from x to the polygon edges, in the length that the
    // parameter step (dU, dV) has on the surface to first order,
    // |dU x_U + dV x_V| (x_U, x_V: the surface tangents at x).
    double
    boundary_distance(const dealii::Point<2>     &x,
                      const dealii::Tensor<1, 3> &x_U,
                      const dealii::Tensor<1, 3> &x_V) const;

    // Whether a polygon edge passes through the open rectangle
    // (u0, u1) x (v0, v1). A loop running along the rectangle's sides does
    // not: then the whole rectangle is inside or outside.
    bool
    crosses(double u0, double u1, double v0, double v1) const;

  private:
    std::vector<std::vector<dealii::Point<2>>> loop_list;
    double                                     loop_tolerance;
    // Per loop: U min, U max, V min, V max of its vertices.
    std::vector<std::array<double, 4>> loop_boxes;
  };

  // Shortest distance from x to an open polyline (vertex 0 to the last), in
  // the same surface length as TrimmedDomain::boundary_distance.
  double
  polyline_distance(const std::vector<dealii::Point<2>> &polyline,
                    const dealii::Point<2>              &x,
                    const dealii::Tensor<1, 3>          &x_U,
                    const dealii::Tensor<1, 3>          &x_V);

  // How one patch lies in a trimmed face. A null domain: the patch is not
  // trimmed (every foot on it counts).
  struct PatchTrimming
  {
    std::shared_ptr<const TrimmedDomain> domain;
    // U = u0 + du s, V = v0 + dv t.
    double u0 = 0., du = 1., v0 = 0., dv = 1.;

    bool
    trimmed() const;

    // Is the foot (s, t), with tangents x_s, x_t, inside the loops or within
    // the domain's tolerance of them?
    bool
    contains(double                      s,
             double                      t,
             const dealii::Tensor<1, 3> &x_s,
             const dealii::Tensor<1, 3> &x_t) const;
  };
} // namespace deepdraw::geometry

#endif
