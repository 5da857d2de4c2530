// Tensor-product rational Bézier patch of degrees (p, q):
//   x(u, v) = sum_ij B_i^p(u) B_j^q(v) w_ij P_ij / sum_ij B_i^p(u) B_j^q(v)
//   w_ij,
// (u, v) in [0, 1]^2 (Piegl & Tiller, The NURBS Book, Eq. 4.15 with Bézier
// knots). Positive weights give the convex-hull property, so the box of the
// control net bounds the surface; the coarse contact search relies on it.
// Circular arcs, cylinders, spheres and tori are exact with rational weights.
#ifndef deepdraw_geometry_bezier_patch_h
#define deepdraw_geometry_bezier_patch_h

#include <array>
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deepdraw/geometry/surface_point.h>
#include <vector>

namespace deepdraw::geometry
{
  // Result of the closest-point projection of a point onto one patch.
  struct PatchProjection
  {
    double       u = 0., v = 0.;
    SurfacePoint point;
    // |x - foot|.
    double distance = 0.;
    // For each edge (0: u = 0, 1: u = 1, 2: v = 0, 3: v = 1, deal.II's face
    // numbering of a quadrilateral): how far the projected point lies beyond
    // that edge, measured along the tangent across it; zero unless the
    // unconstrained closest point lies outside the patch there, i.e. unless
    // the foot point had to be clamped onto that edge.
    std::array<double, 4> beyond_edge = {{0., 0., 0., 0.}};
    unsigned int          iterations  = 0;
  };

  class BezierPatch
  {
  public:
    // Fixed-size work arrays keep evaluation free of allocations; tools need
    // far lower degrees than this.
    static constexpr unsigned int max_degree = 15;

    // Control points and weights are ordered with the u index running
    // fastest: entry i + (p + 1) j holds P_ij. Weights must be positive.
    BezierPatch(unsigned int                         degree_u,
                unsigned int                         degree_v,
                const std::vector<dealii::Point<3>> &control_points,
                const std::vector<double>           &weights);

    unsigned int
    degree_u() const;
    unsigned int
    degree_v() const;
    const std::vector<dealii::Point<3>> &
    control_points() const;
    const std::vector<double> &
    weights() const;
    const dealii::Point<3> &
    control_point(unsigned int i, unsigned int j) const;
    double
    weight(unsigned int i, unsigned int j) const;

    dealii::Point<3>
    value(double u, double v) const;
    // Position, first and second derivatives (quotient rule of the
    // homogeneous form, The NURBS Book Eq. 4.20).
    SurfacePoint
    derivatives(double u, double v) const;
    // (x_u × x_v) / |x_u × x_v|: the parametrisation fixes the orientation.
    dealii::Tensor<1, 3>
    unit_normal(double u, double v) const;
    // Principal curvatures, convention of SurfaceCurvature.
    std::array<double, 2>
    principal_curvatures(double u, double v) const;

    // Box of the control net; contains the patch.
    const dealii::BoundingBox<3> &
    bounding_box() const;
    // A length that sets the tolerances of the patch (largest of the box
    // diagonal and the largest coordinate magnitude).
    double
    length_scale() const;

    // Closest point on the patch: best of a sample grid, then Newton on
    // (u, v) for min |x(u, v) - x|^2 / 2 with the exact Hessian (Gauss-Newton
    // where it is not positive definite), the iterate projected onto [0, 1]^2
    // and the active bounds fixed while the gradient pushes outwards.
    PatchProjection
    closest_point(const dealii::Point<3> &x) const;

    // The same surface with u running backwards, i.e. the opposite normal.
    BezierPatch
    reversed_u() const;

  private:
    unsigned int                  p, q;
    std::vector<dealii::Point<3>> points;
    std::vector<double>           point_weights;
    // (w x, w y, w z, w) per control point: the polynomial patch in R^4.
    std::vector<std::array<double, 4>> homogeneous;
    dealii::BoundingBox<3>             box;
    double                             scale;
    // Initial guesses for the projection: a grid of surface points.
    unsigned int                  n_samples_u, n_samples_v;
    std::vector<dealii::Point<3>> samples;
  };
} // namespace deepdraw::geometry

#endif
