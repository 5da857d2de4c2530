// Closest-point projection onto single rational patches against analytic
// distances: a plane (rational (2, 3) patch, placed by a rotation and a
// translation), a cylinder, a sphere zone and two tori, with points inside,
// outside, near edges and near corners. Gap and foot point to 1e-10.
#include "test_utilities.h"

#include <cmath>
#include <deepdraw/geometry/bezier_shapes.h>
#include <deepdraw/geometry/rigid_tool.h>
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

  // Angle in [mid - half, mid + half] closest (along the circle) to angle.
  double
  clamp_angle(const double angle, const double mid, const double half)
  {
    const double delta = std::remainder(angle - mid, 2 * M_PI);
    return mid + std::max(-half, std::min(half, delta));
  }

  struct Expected
  {
    Point<3> foot;
    Vector   normal;
  };

  struct Statistics
  {
    double       gap_error = 0., foot_error = 0., normal_error = 0.;
    unsigned int n_points = 0, n_on_edge = 0, n_failed = 0;
  };

  void
  compare(const RigidTool &tool,
          const Point<3>  &x,
          const Expected  &expected,
          Statistics      &stats)
  {
    ProjectionResult result;
    if (!tool.project(x, result, 1e3))
    {
      ++stats.n_failed;
      return;
    }
    const double gap = (x - expected.foot) * expected.normal;
    stats.gap_error  = std::max(stats.gap_error, std::abs(result.gap - gap));
    stats.foot_error
      = std::max(stats.foot_error, (result.foot - expected.foot).norm());
    stats.normal_error
      = std::max(stats.normal_error, (result.normal - expected.normal).norm());
    ++stats.n_points;
    if (result.on_edge)
      ++stats.n_on_edge;
  }

  void
  report(const std::string &name,
         const Statistics  &stats,
         const unsigned int min_on_edge)
  {
    std::cout << name << ": " << stats.n_points << " points, "
              << stats.n_on_edge << " with the foot clamped onto an edge"
              << std::endl;
    check_true(name + ": every projection found", stats.n_failed == 0);
    check_close(name + ": max |gap - analytic gap|",
                stats.gap_error,
                0.,
                1e-10);
    check_close(name + ": max |foot - analytic foot|",
                stats.foot_error,
                0.,
                1e-10);
    check_close(name + ": max |normal - analytic normal|",
                stats.normal_error,
                0.,
                1e-10);
    check_true(name + ": edge and corner cases present",
               stats.n_on_edge >= min_on_edge);
  }
} // namespace

int
main()
{
  std::mt19937                           rng(7);
  std::uniform_real_distribution<double> uniform(0., 1.);
  const auto                             between
    = [&](double a, double b) { return a + (b - a) * uniform(rng); };

  // Plane: rectangle [0, 30] x [0, 20] spanned by e1, e2 from O, as a
  // rational (2, 3) patch with uneven weights (a non-affine parametrisation
  // of the rectangle), in a tool rotated and translated in space.
  {
    const double          Lx = 30., Ly = 20.;
    const Point<3>        origin(1., 2., 3.);
    const Vector          e1 = vec(1, 1, 0) / std::sqrt(2.);
    const Vector          e2 = vec(-1, 1, 1) / std::sqrt(3.);
    const Vector          n  = dealii::cross_product_3d(e1, e2);
    std::vector<Point<3>> points;
    std::vector<double>   weights;
    for (unsigned int j = 0; j <= 3; ++j)
      for (unsigned int i = 0; i <= 2; ++i)
      {
        points.push_back(origin + (Lx * i / 2.) * e1 + (Ly * j / 3.) * e2);
        weights.push_back(0.6 + 0.9 * uniform(rng));
      }
    RigidTool tool("plane");
    tool.add_patch(BezierPatch(2, 3, points, weights));

    // Rotation about (1, 2, 3) by 0.7 rad, translation (5, -3, 2).
    const Vector         axis = vec(1, 2, 3) / std::sqrt(14.);
    dealii::Tensor<2, 3> rotation;
    for (unsigned int d = 0; d < 3; ++d)
    {
      Vector unit;
      unit[d]             = 1.;
      const Vector column = rotate(unit, axis, 0.7);
      for (unsigned int e = 0; e < 3; ++e)
        rotation[e][d] = column[e];
    }
    const Vector translation = vec(5, -3, 2);
    tool.set_rigid_motion(rotation, translation);
    const Point<3> O  = Point<3>(rotation * origin + translation);
    const Vector   E1 = rotation * e1, E2 = rotation * e2, N = rotation * n;

    Statistics stats;
    const auto run = [&](double a, double b, double h)
    {
      const Point<3> x = O + a * E1 + b * E2 + h * N;
      const Point<3> foot
        = O + std::clamp(a, 0., Lx) * E1 + std::clamp(b, 0., Ly) * E2;
      compare(tool, x, {foot, N}, stats);
    };
    for (unsigned int k = 0; k < 2000; ++k)
      run(between(-0.3 * Lx, 1.3 * Lx),
          between(-0.3 * Ly, 1.3 * Ly),
          between(-3, 3));
    // Just inside and just outside every edge and corner.
    for (const double a : {-1e-3,
                           -1e-7,
                           1e-7,
                           1e-3,
                           Lx / 3,
                           Lx - 1e-3,
                           Lx - 1e-7,
                           Lx + 1e-7,
                           Lx + 1e-3})
      for (const double b : {-1e-3,
                             -1e-7,
                             1e-7,
                             1e-3,
                             Ly / 2,
                             Ly - 1e-3,
                             Ly - 1e-7,
                             Ly + 1e-7,
                             Ly + 1e-3})
        for (const double h : {-0.5, 0., 0.5})
          run(a, b, h);
    report("rotated and translated rational plane", stats, 500);
  }

  // Cylinder: radius 8, 120-degree arc from 20 degrees, z in [-1, 3],
  // normal outward.
  {
    const double R = 8., phi_0 = 20 * M_PI / 180, span = 120 * M_PI / 180,
                 z0 = -1., z1 = 3.;
    RigidTool tool("cylinder");
    tool.add_patch(
      extruded_patch(circular_arc(Point<3>(0, 0, z0),
                                  R * vec(std::cos(phi_0), std::sin(phi_0), 0),
                                  vec(0, 0, 1),
                                  span),
                     (z1 - z0) * vec(0, 0, 1)));
    Statistics stats;
    const auto run = [&](double rho, double phi, double z)
    {
      const Point<3> x(rho * std::cos(phi), rho * std::sin(phi), z);
      const double   phi_c = clamp_angle(phi, phi_0 + span / 2, span / 2);
      const Vector   n     = vec(std::cos(phi_c), std::sin(phi_c), 0);
      compare(tool,
              x,
              {Point<3>(R * n[0], R * n[1], std::clamp(z, z0, z1)), n},
              stats);
    };
    for (unsigned int k = 0; k < 2000; ++k)
      run(between(0.3 * R, 1.6 * R),
          between(phi_0 - 0.5, phi_0 + span + 0.5),
          between(z0 - 1, z1 + 1));
    for (const double dphi : {-1e-4, -1e-8, 1e-8, 1e-4})
      for (const double z : {z0 - 1e-3, z0 + 1e-8, 1., z1 - 1e-8, z1 + 1e-3})
        for (const double rho : {0.5 * R, R, R + 1e-9, 1.2 * R})
        {
          run(rho, phi_0 + dphi, z);
          run(rho, phi_0 + span + dphi, z);
        }
    report("cylinder", stats, 500);
  }

  // Sphere zone: radius 6, latitude 0..60 degrees, longitude 0..90 degrees.
  {
    const double R = 6., lat_1 = M_PI / 3, lon_1 = M_PI / 2;
    RigidTool    tool("sphere");
    tool.add_patch(revolved_patch(
      circular_arc(Point<3>(), R * vec(1, 0, 0), vec(0, -1, 0), lat_1),
      Point<3>(),
      vec(0, 0, 1),
      lon_1));
    Statistics stats;
    const auto run = [&](double r, double lat, double lon)
    {
      const Point<3> x(r * std::cos(lat) * std::cos(lon),
                       r * std::cos(lat) * std::sin(lon),
                       r * std::sin(lat));
      // Longitude first (independent of the latitude since cos(lat) > 0 on
      // the zone), then the latitude in the meridian plane of lon_c.
      const double lon_c = clamp_angle(lon, lon_1 / 2, lon_1 / 2);
      const double rho   = std::hypot(x[0], x[1])
                         * std::cos(std::remainder(lon - lon_c, 2 * M_PI));
      const double lat_c
        = clamp_angle(std::atan2(x[2], rho), lat_1 / 2, lat_1 / 2);
      const Vector n = vec(std::cos(lat_c) * std::cos(lon_c),
                           std::cos(lat_c) * std::sin(lon_c),
                           std::sin(lat_c));
      compare(tool, x, {Point<3>(R * n), n}, stats);
    };
    for (unsigned int k = 0; k < 2000; ++k)
      run(between(0.4 * R, 1.6 * R),
          between(-0.35, lat_1 + 0.35),
          between(-0.35, lon_1 + 0.35));
    for (const double d : {-1e-4, -1e-8, 1e-8, 1e-4})
      for (const double r : {0.5 * R, R, 1.3 * R})
      {
        run(r, d, 0.4);
        run(r, lat_1 + d, 0.4);
        run(r, 0.5, d);
        run(r, 0.5, lon_1 + d);
        run(r, d, d);
        run(r, lat_1 + d, lon_1 + d);
      }
    report("sphere zone", stats, 300);
  }

  // Tori: the die-shoulder corner (R = 20, r = 8, tube angle 90..180
  // degrees) and the punch-nose corner (R = 2, r = 8, -90..0 degrees), both
  // over longitudes 0..90 degrees, normal outward from the tube.
  struct TorusCase
  {
    std::string name;
    double      R, r, alpha_0, zc;
  };
  for (const TorusCase &c :
       {TorusCase{"die shoulder torus", 20., 8., M_PI / 2, -8.},
        TorusCase{"punch nose torus", 2., 8., -M_PI / 2, 8.81}})
  {
    const double span = M_PI / 2, lon_1 = M_PI / 2;
    const Vector start = c.r * vec(std::cos(c.alpha_0), 0, std::sin(c.alpha_0));
    RigidTool    tool(c.name);
    tool.add_patch(oriented_towards(
      revolved_patch(
        circular_arc(Point<3>(c.R, 0, c.zc), start, vec(0, -1, 0), span),
        Point<3>(),
        vec(0, 0, 1),
        lon_1),
      vec(std::cos(c.alpha_0 + span / 2),
          std::cos(c.alpha_0 + span / 2),
          std::sin(c.alpha_0 + span / 2))));
    Statistics stats;
    const auto run = [&](double d, double alpha, double lon)
    {
      const double rho = c.R + d * std::cos(alpha);
      if (rho < 0.5)
        return; // too close to the axis for the analytic formula
      const Point<3> x(rho * std::cos(lon),
                       rho * std::sin(lon),
                       c.zc + d * std::sin(alpha));
      // Longitude first (R + r cos(alpha) > 0 on the patch), then the tube
      // angle in the meridian plane of lon_c.
      const double lon_c = clamp_angle(lon, lon_1 / 2, lon_1 / 2);
      const double rho_m
        = rho * std::cos(std::remainder(lon - lon_c, 2 * M_PI));
      const double   alpha_c = clamp_angle(std::atan2(x[2] - c.zc, rho_m - c.R),
                                         c.alpha_0 + span / 2,
                                         span / 2);
      const Vector   n       = vec(std::cos(alpha_c) * std::cos(lon_c),
                           std::cos(alpha_c) * std::sin(lon_c),
                           std::sin(alpha_c));
      const Point<3> foot((c.R + c.r * std::cos(alpha_c)) * std::cos(lon_c),
                          (c.R + c.r * std::cos(alpha_c)) * std::sin(lon_c),
                          c.zc + c.r * std::sin(alpha_c));
      compare(tool, x, {foot, n}, stats);
    };
    for (unsigned int k = 0; k < 3000; ++k)
      run(between(0.3 * c.r, 1.6 * c.r),
          between(c.alpha_0 - 0.5, c.alpha_0 + span + 0.5),
          between(-0.3, lon_1 + 0.3));
    for (const double e : {-1e-4, -1e-8, 1e-8, 1e-4})
      for (const double d : {0.5 * c.r, c.r, 1.3 * c.r})
      {
        run(d, c.alpha_0 + e, 0.7);
        run(d, c.alpha_0 + span + e, 0.7);
        run(d, c.alpha_0 + 0.6, e);
        run(d, c.alpha_0 + 0.6, lon_1 + e);
        run(d, c.alpha_0 + e, e);
        run(d, c.alpha_0 + span + e, lon_1 + e);
      }
    report(c.name, stats, 500);
  }
  return summary();
}
