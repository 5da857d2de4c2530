// BezierPatch evaluation: derivatives against finite differences on a
// general rational patch; exact conics (sphere, torus) against their
// implicit equations; unit normals and principal curvatures against the
// analytic values; convex-hull property of the control-net box.
#include "test_utilities.h"

#include <cmath>
#include <deepdraw/geometry/bezier_patch.h>
#include <deepdraw/geometry/bezier_shapes.h>
#include <random>

using namespace deepdraw::geometry;
using namespace deepdraw_test;
using dealii::Point;
using Vector = dealii::Tensor<1, 3>;

namespace
{
  Vector
  vec(double x, double y, double z)
  {
    return Point<3>(x, y, z);
  }
} // namespace

int
main()
{
  std::mt19937                           rng(42);
  std::uniform_real_distribution<double> uniform(0., 1.);

  // A general rational patch of degrees (3, 2): derivatives vs central
  // differences (step 1e-5: truncation ~1e-10, round-off ~1e-11).
  {
    std::vector<Point<3>> points;
    std::vector<double>   weights;
    for (unsigned int j = 0; j <= 2; ++j)
      for (unsigned int i = 0; i <= 3; ++i)
      {
        points.emplace_back(i + 0.3 * uniform(rng),
                            j + 0.3 * uniform(rng),
                            2. * uniform(rng));
        weights.push_back(0.5 + uniform(rng));
      }
    const BezierPatch patch(3, 2, points, weights);
    const double      h       = 1e-5;
    double            error_1 = 0., error_2 = 0., error_value = 0.;
    for (unsigned int n = 0; n < 20; ++n)
    {
      const double u = 0.05 + 0.9 * uniform(rng), v = 0.05 + 0.9 * uniform(rng);
      const SurfacePoint s = patch.derivatives(u, v);
      const auto x = [&](double a, double b) { return patch.value(a, b); };
      error_value  = std::max(error_value, (s.position - x(u, v)).norm());
      error_1
        = std::max(error_1,
                   (s.x_u - (x(u + h, v) - x(u - h, v)) / (2 * h)).norm());
      error_1
        = std::max(error_1,
                   (s.x_v - (x(u, v + h) - x(u, v - h)) / (2 * h)).norm());
      const auto du
        = [&](double a, double b) { return patch.derivatives(a, b).x_u; };
      const auto dv
        = [&](double a, double b) { return patch.derivatives(a, b).x_v; };
      error_2
        = std::max(error_2,
                   (s.x_uu - (du(u + h, v) - du(u - h, v)) / (2 * h)).norm());
      error_2
        = std::max(error_2,
                   (s.x_uv - (du(u, v + h) - du(u, v - h)) / (2 * h)).norm());
      error_2
        = std::max(error_2,
                   (s.x_uv - (dv(u + h, v) - dv(u - h, v)) / (2 * h)).norm());
      error_2
        = std::max(error_2,
                   (s.x_vv - (dv(u, v + h) - dv(u, v - h)) / (2 * h)).norm());
    }
    check_close("general patch: value() == derivatives().position",
                error_value,
                0.,
                1e-14);
    check_close("general patch: first derivatives vs central differences",
                error_1,
                0.,
                1e-8);
    check_close("general patch: second derivatives vs central differences",
                error_2,
                0.,
                1e-7);

    // Corners interpolate the corner control points.
    check_close("corner (0,0) = P_00",
                (patch.value(0, 0) - points[0]).norm(),
                0.,
                1e-14);
    check_close("corner (1,1) = P_32",
                (patch.value(1, 1) - points[11]).norm(),
                0.,
                1e-14);

    // Convex hull: all surface points inside the control-net box.
    bool inside = true;
    for (unsigned int n = 0; n < 1000; ++n)
      inside = inside
               && patch.bounding_box().point_inside(patch.value(uniform(rng),
                                                                uniform(rng)),
                                                    1e-12);
    check_true("1000 surface points inside the control-net box", inside);

    // Reversing u flips the normal, keeps the surface.
    const BezierPatch reversed = patch.reversed_u();
    check_close("reversed_u: same point",
                (reversed.value(0.3, 0.6) - patch.value(0.7, 0.6)).norm(),
                0.,
                1e-14);
    check_close(
      "reversed_u: opposite normal",
      (reversed.unit_normal(0.3, 0.6) + patch.unit_normal(0.7, 0.6)).norm(),
      0.,
      1e-14);
  }

  // Sphere zone: radius 5, latitude 0..60 degrees, longitude 0..90 degrees.
  {
    const double R = 5.;
    const auto   profile
      = circular_arc(Point<3>(), R * vec(1, 0, 0), vec(0, -1, 0), M_PI / 3);
    const BezierPatch sphere
      = revolved_patch(profile, Point<3>(), vec(0, 0, 1), M_PI / 2);
    double radius_error = 0., normal_error = 0., curvature_error = 0.;
    for (unsigned int n = 0; n < 200; ++n)
    {
      const double   u = uniform(rng), v = uniform(rng);
      const Point<3> x = sphere.value(u, v);
      radius_error     = std::max(radius_error, std::abs(x.norm() - R));
      normal_error
        = std::max(normal_error, (sphere.unit_normal(u, v) - x / R).norm());
      const auto kappa = sphere.principal_curvatures(u, v);
      curvature_error  = std::max({curvature_error,
                                   std::abs(kappa[0] - 1 / R),
                                   std::abs(kappa[1] - 1 / R)});
    }
    check_close("sphere patch: |x| - R", radius_error, 0., 1e-13);
    check_close("sphere patch: normal = x / R (outward)",
                normal_error,
                0.,
                1e-13);
    check_close("sphere patch: principal curvatures = 1/R",
                curvature_error,
                0.,
                1e-12);
    check_close(
      "sphere patch: corner (1,1) at latitude 60, longitude 90",
      (sphere.value(1, 1) - Point<3>(0, R * 0.5, R * std::sqrt(0.75))).norm(),
      0.,
      1e-14);
  }

  // Torus patch (punch nose corner): major radius 2, tube radius 8, tube
  // angle from -90 to 0 degrees; curvatures 1/r and cos(a) / (R + r cos(a)).
  {
    const double      R = 2., r = 8., zc = 8.81;
    const auto        profile = circular_arc(Point<3>(R, 0, zc),
                                      r * vec(0, 0, -1),
                                      vec(0, -1, 0),
                                      M_PI / 2);
    const BezierPatch torus   = oriented_towards(
      revolved_patch(profile, Point<3>(0, 0, 0), vec(0, 0, 1), M_PI / 2),
      vec(1, 1, -1.4));
    double implicit_error = 0., normal_error = 0., curvature_error = 0.;
    for (unsigned int n = 0; n < 200; ++n)
    {
      const double   u = uniform(rng), v = uniform(rng);
      const Point<3> x   = torus.value(u, v);
      const double   rho = std::hypot(x[0], x[1]);
      implicit_error     = std::max(implicit_error,
                                std::abs(std::hypot(rho - R, x[2] - zc) - r));
      // Outward from the tube centre circle.
      const Vector expected
        = (x - Point<3>(R * x[0] / rho, R * x[1] / rho, zc)) / r;
      normal_error
        = std::max(normal_error, (torus.unit_normal(u, v) - expected).norm());
      const double cos_a = (rho - R) / r;
      const double k1 = 1 / r, k2 = cos_a / (R + r * cos_a);
      const auto   kappa = torus.principal_curvatures(u, v);
      curvature_error    = std::max({curvature_error,
                                     std::abs(kappa[0] - std::min(k1, k2)),
                                     std::abs(kappa[1] - std::max(k1, k2))});
    }
    check_close("torus patch: distance to the tube centre circle - r",
                implicit_error,
                0.,
                1e-13);
    check_close("torus patch: normal outward from the tube",
                normal_error,
                0.,
                1e-13);
    check_close("torus patch: principal curvatures 1/r, cos a/(R + r cos a)",
                curvature_error,
                0.,
                1e-12);
  }

  // Cylinder: curvatures 0 and 1/R.
  {
    const double      R = 12.;
    const BezierPatch cylinder
      = extruded_patch(circular_arc(Point<3>(25, 25, -8),
                                    R * vec(1, 0, 0),
                                    vec(0, 0, 1),
                                    M_PI / 2),
                       vec(0, 0, -42));
    const auto kappa = cylinder.principal_curvatures(0.3, 0.7);
    // Normal x_u × x_v of this extrusion points to the axis: concave side.
    check_close("cylinder: smaller principal curvature = -1/R",
                kappa[0],
                -1 / R,
                1e-13);
    check_close("cylinder: larger principal curvature = 0",
                kappa[1],
                0.,
                1e-13);
  }
  return summary();
}
