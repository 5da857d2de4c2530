// NUMISHEET'93 square-cup tools: dimensions and radii, G1 continuity of
// adjacent patches, continuous gap and normal for points sweeping across
// every patch junction (a node sliding from a flat onto a radius), the
// expected free edges, the motion, and the parameters.
#include "test_utilities.h"

#include <cmath>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/geometry/square_cup_tools.h>
#include <deepdraw/io/input_error.h>
#include <random>
#include <sstream>
#include <thread>

using namespace deepdraw::geometry;
using namespace deepdraw_test;
using dealii::Point;
using Vector = dealii::Tensor<1, 3>;

namespace
{
  const double thickness = 0.81;

  // Parameters of sample t along edge e of a patch.
  std::pair<double, double>
  on_edge(const unsigned int e, const double t)
  {
    return e == 0   ? std::make_pair(0., t)
           : e == 1 ? std::make_pair(1., t)
           : e == 2 ? std::make_pair(t, 0.)
                    : std::make_pair(t, 1.);
  }

  // Every edge that is not free and not on a symmetry plane must be
  // continued by another patch with the same position and normal (G1);
  // then sweeps across the junction at its middle: along the offset
  // surface at distance h the gap must stay h; along a straight line across
  // the junction the gap and the normal must have no jump (their second
  // differences on a 1e-6 grid stay at round-off).
  void
  check_junctions(const RigidTool &tool)
  {
    const std::string name         = tool.name();
    double            position_gap = 0., normal_jump = 0., offset_error = 0.;
    double            gap_jump = 0., normal_step = 0., slope_excess = 0.;
    unsigned int      n_junctions = 0, n_unmatched = 0;
    for (unsigned int k = 0; k < tool.n_patches(); ++k)
      for (unsigned int e = 0; e < 4; ++e)
      {
        if (tool.is_free_edge(k, e)
            || tool.declared_edge_kinds(k)[e] == EdgeKind::symmetry)
          continue;
        const BezierPatch &patch = tool.patch(k);
        for (unsigned int m = 0; m <= 10; ++m)
        {
          const auto [u, v] = on_edge(e, m / 10.);
          const Point<3> x  = patch.value(u, v);
          // The neighbour: another patch through x.
          bool matched = false;
          for (unsigned int j = 0; j < tool.n_patches() && !matched; ++j)
          {
            if (j == k)
              continue;
            const PatchProjection other = tool.patch(j).closest_point(x);
            if (other.distance > 1e-8)
              continue;
            matched      = true;
            position_gap = std::max(position_gap, other.distance);
            normal_jump  = std::max(
              normal_jump,
              (unit_normal(other.point) - patch.unit_normal(u, v)).norm());
            if (m != 5)
              continue;

            // Sweeps at the middle of the edge. tau: tangent across
            // the edge, pointing out of patch k (into patch j).
            ++n_junctions;
            const SurfacePoint s     = patch.derivatives(u, v);
            const Vector       n     = unit_normal(s);
            const Vector       along = (e < 2) ? s.x_v : s.x_u;
            Vector             tau   = dealii::cross_product_3d(n, along);
            tau /= tau.norm();
            const Vector inward = (e == 0)   ? s.x_u
                                  : (e == 1) ? -s.x_u
                                  : (e == 2) ? s.x_v
                                             : -s.x_v;
            if (tau * inward > 0)
              tau = -tau;
            for (const double h : {0.5, 1e-3, 0., -0.1})
            {
              // Offset surface: walk along each patch's parameter
              // line towards the edge, then beyond on the other.
              for (int i = -40; i <= 40; ++i)
              {
                const double t = i / 40.;
                Point<3>     y;
                Vector       ny;
                if (i <= 0)
                {
                  // Parameter line of patch k ending at the edge.
                  const double d  = -t * 0.2;
                  const double uu = (e == 0) ? d : (e == 1) ? 1 - d : u;
                  const double vv = (e == 2) ? d : (e == 3) ? 1 - d : v;
                  y               = patch.value(uu, vv);
                  ny              = patch.unit_normal(uu, vv);
                }
                else
                {
                  // Move on patch j away from the edge along -tau.
                  const PatchProjection start
                    = tool.patch(j).closest_point(x + 1e-3 * t * tau);
                  y  = start.point.position;
                  ny = unit_normal(start.point);
                }
                ProjectionResult result;
                if (!tool.project(y + h * ny, result, 5.))
                {
                  offset_error = 1e300;
                  continue;
                }
                offset_error = std::max(offset_error, std::abs(result.gap - h));
              }
              // Straight line across the junction, grid 1e-6.
              const double step         = 1e-6;
              double       previous_gap = 0., previous_slope = 0.;
              Vector       previous_normal;
              for (int i = -200; i <= 200; ++i)
              {
                ProjectionResult result;
                if (!tool.project(x + h * n + (i * step) * tau, result, 5.))
                {
                  gap_jump = 1e300;
                  continue;
                }
                if (i > -200)
                {
                  const double slope = result.gap - previous_gap;
                  slope_excess = std::max(slope_excess, std::abs(slope) - step);
                  normal_step
                    = std::max(normal_step,
                               (result.normal - previous_normal).norm());
                  if (i > -199)
                    gap_jump
                      = std::max(gap_jump, std::abs(slope - previous_slope));
                  previous_slope = slope;
                }
                previous_gap    = result.gap;
                previous_normal = result.normal;
              }
            }
          }
          if (!matched)
            ++n_unmatched;
        }
      }
    std::cout << name << ": " << n_junctions << " junctions swept" << std::endl;
    check_true(name
                 + ": every non-free edge sample lies on a neighbouring patch",
               n_unmatched == 0);
    check_close(name + ": position gap between adjacent patches",
                position_gap,
                0.,
                1e-10);
    check_close(name + ": normal jump between adjacent patches",
                normal_jump,
                0.,
                1e-10);
    check_close(name + ": offset-surface sweeps, max |gap - h|",
                offset_error,
                0.,
                1e-10);
    check_close(name + ": straight sweeps, max |second difference of gap|",
                gap_jump,
                0.,
                1e-9);
    check_close(name + ": straight sweeps, max (|gap step| - step)",
                std::max(slope_excess, 0.),
                0.,
                1e-9);
    // |dn/ds| <= curvature / (1 - h curvature) <= 1/7.9 for these tools.
    check_close(name + ": straight sweeps, max |normal step| on a 1e-6 grid",
                normal_step,
                0.,
                1e-6 / 7.9 * 1.01);
  }

  unsigned int
  count_free_edges(const RigidTool &tool)
  {
    unsigned int n = 0;
    for (unsigned int k = 0; k < tool.n_patches(); ++k)
      for (unsigned int e = 0; e < 4; ++e)
        n += tool.is_free_edge(k, e);
    return n;
  }

  // max | distance of the patch points from a circle or line - radius |.
  template <typename Distance>
  double
  radius_error(const BezierPatch &patch,
               const Distance    &distance,
               const double       radius)
  {
    double error = 0.;
    for (unsigned int i = 0; i <= 20; ++i)
      for (unsigned int j = 0; j <= 20; ++j)
        error = std::max(error,
                         std::abs(distance(patch.value(i / 20., j / 20.))
                                  - radius));
    return error;
  }
} // namespace

int
main()
{
  SquareCupToolParameters parameters;
  std::vector<RigidTool>  tools = build_square_cup_tools(parameters, thickness);
  check_true("three tools", tools.size() == 3);
  const RigidTool &punch = tools[0], &die = tools[1], &holder = tools[2];
  check_true("names punch, die, blank holder",
             punch.name() == "punch" && die.name() == "die"
               && holder.name() == "blank holder");
  check_true("quarter model: 12 punch, 10 die, 4 blank-holder patches",
             punch.n_patches() == 12 && die.n_patches() == 10
               && holder.n_patches() == 4);

  // Placement and extent (control-net boxes; planes and arcs reach them).
  const auto check_box
    = [](const RigidTool &tool, const Point<3> &low, const Point<3> &high)
  {
    const auto &corners = tool.bounding_box().get_boundary_points();
    check_close(tool.name() + ": box lower corner",
                corners.first.distance(low),
                0.,
                1e-12);
    check_close(tool.name() + ": box upper corner",
                corners.second.distance(high),
                0.,
                1e-12);
  };
  check_box(punch, Point<3>(0, 0, thickness), Point<3>(35, 35, thickness + 50));
  check_box(die, Point<3>(0, 0, -50), Point<3>(100, 100, 0));
  check_box(holder, Point<3>(0, 0, thickness), Point<3>(100, 100, thickness));

  // Radii. Punch nose: tube centre line x = 27 (y = 27), z = t + 8, and
  // tube centre circle of radius 2 about (25, 25) in the corner.
  const double zc = thickness + 8;
  check_close("punch nose (x side): distance from the tube axis - 8",
              radius_error(
                punch.patch(6),
                [&](const Point<3> &x)
                { return std::hypot(x[0] - 27, x[2] - zc); },
                8.),
              0.,
              1e-12);
  check_close("punch nose (corner): distance from the tube circle - 8",
              radius_error(
                punch.patch(7),
                [&](const Point<3> &x) {
                  return std::hypot(std::hypot(x[0] - 25, x[1] - 25) - 2,
                                    x[2] - zc);
                },
                8.),
              0.,
              1e-12);
  check_close("punch nose (y side): distance from the tube axis - 8",
              radius_error(
                punch.patch(8),
                [&](const Point<3> &x)
                { return std::hypot(x[1] - 27, x[2] - zc); },
                8.),
              0.,
              1e-12);
  check_close("punch wall corner: plan radius 10 about (25, 25)",
              radius_error(
                punch.patch(10),
                [&](const Point<3> &x)
                { return std::hypot(x[0] - 25, x[1] - 25); },
                10.),
              0.,
              1e-12);
  check_close(
    "punch face corner: plan radius 2 about (25, 25) on the arc edges",
    std::max(std::abs(punch.patch(4).value(0.37, 0.).distance(
                        Point<3>(25, 25, thickness))
                      - 2),
             std::abs(punch.patch(5).value(0.81, 0.).distance(
                        Point<3>(25, 25, thickness))
                      - 2)),
    0.,
    1e-12);
  check_close("die shoulder (x side): distance from the tube axis - 8",
              radius_error(
                die.patch(4),
                [&](const Point<3> &x)
                { return std::hypot(x[0] - 45, x[2] + 8); },
                8.),
              0.,
              1e-12);
  check_close("die shoulder (corner): distance from the tube circle - 8",
              radius_error(
                die.patch(5),
                [&](const Point<3> &x) {
                  return std::hypot(std::hypot(x[0] - 25, x[1] - 25) - 20,
                                    x[2] + 8);
                },
                8.),
              0.,
              1e-12);
  check_close("die wall corner: plan radius 12 about (25, 25)",
              radius_error(
                die.patch(8),
                [&](const Point<3> &x)
                { return std::hypot(x[0] - 25, x[1] - 25); },
                12.),
              0.,
              1e-12);
  {
    const auto kappa = punch.patch(7).principal_curvatures(0.5, 0.5);
    check_close("punch nose corner: tube curvature 1/8",
                kappa[1],
                1 / 8.,
                1e-12);
    const auto kappa_die = die.patch(4).principal_curvatures(0.3, 0.6);
    check_close("die shoulder: curvature 1/8 (convex towards the sheet)",
                kappa_die[1],
                1 / 8.,
                1e-12);
  }

  // Normals towards the sheet at characteristic points.
  {
    ProjectionResult r;
    punch.project(Point<3>(10, 10, 0.), r, 5.);
    check_close("punch face normal z", r.normal[2], -1., 1e-14);
    check_close("punch face gap below it", r.gap, thickness, 1e-13);
    die.project(Point<3>(60, 10, 0.81), r, 5.);
    check_close("die face normal z", r.normal[2], 1., 1e-14);
    check_close("die face gap above it", r.gap, 0.81, 1e-13);
    holder.project(Point<3>(60, 60, 0.5), r, 5.);
    check_close("blank holder normal z", r.normal[2], -1., 1e-14);
    check_close("blank holder gap", r.gap, 0.31, 1e-13);
    die.project(Point<3>(36, 10, -20), r, 5.);
    check_close("die wall normal x (into the opening)",
                r.normal[0],
                -1.,
                1e-14);
    punch.project(Point<3>(36, 10, 20), r, 5.);
    check_close("punch wall normal x (outwards)", r.normal[0], 1., 1e-14);
    // Die shoulder at 45 degrees: foot at (45 - 8 s, y, -8 + 8 s).
    const double s = std::sqrt(0.5);
    die.project(Point<3>(45 - 9 * s, 12, -8 + 9 * s), r, 5.);
    check_close("die shoulder gap at 45 degrees", r.gap, 1., 1e-12);
    check_close("die shoulder foot x at 45 degrees",
                r.foot[0],
                45 - 8 * s,
                1e-12);
  }

  // Free edges: punch wall tops (3); die outer face edges (4) and wall
  // bottoms (3); blank holder inner contour (4) and outer edges (4).
  check_true("punch: 3 free edges (wall tops)", count_free_edges(punch) == 3);
  check_true("die: 7 free edges (outer face edges, wall bottoms)",
             count_free_edges(die) == 7);
  check_true("blank holder: 8 free edges (inner contour, outer edges)",
             count_free_edges(holder) == 8);

  for (const RigidTool &tool : tools)
    check_junctions(tool);

  // Concurrent const projections (as the solver does) give the serial
  // results bit for bit.
  {
    std::mt19937                           rng(11);
    std::uniform_real_distribution<double> uniform(0., 1.);
    std::vector<Point<3>>                  points(40000);
    for (Point<3> &x : points)
      x = Point<3>(50 * uniform(rng),
                   50 * uniform(rng),
                   -5 + 10 * uniform(rng));
    std::vector<ProjectionResult> serial(points.size()),
      parallel(points.size());
    std::vector<char> found_serial(points.size()),
      found_parallel(points.size());
    for (unsigned int k = 0; k < points.size(); ++k)
      found_serial[k] = die.project(points[k], serial[k], 6.);
    std::vector<std::thread> threads;
    for (unsigned int t = 0; t < 4; ++t)
      threads.emplace_back(
        [&, t]()
        {
          for (unsigned int k = t; k < points.size(); k += 4)
            found_parallel[k] = die.project(points[k], parallel[k], 6.);
        });
    for (std::thread &thread : threads)
      thread.join();
    bool same = true;
    for (unsigned int k = 0; k < points.size(); ++k)
      same = same && found_serial[k] == found_parallel[k]
             && (!found_serial[k]
                 || (serial[k].gap == parallel[k].gap
                     && serial[k].foot == parallel[k].foot
                     && serial[k].patch == parallel[k].patch));
    check_true("4 threads projecting concurrently: identical to serial", same);
  }

  // Motion: punch travel 5 mm moves the face to z = t - 5.
  {
    tools[0].set_rigid_motion(dealii::unit_symmetric_tensor<3>(),
                              dealii::Tensor<1, 3>({0., 0., -5.}));
    ProjectionResult r;
    tools[0].project(Point<3>(3, 4, -10), r, 20.);
    check_close("punch after 5 mm travel: foot z",
                r.foot[2],
                thickness - 5,
                1e-13);
    check_close("punch after 5 mm travel: foot in tool frame z",
                r.foot_in_tool_frame[2],
                thickness,
                1e-13);
    check_close("punch after 5 mm travel: box lower z",
                tools[0].bounding_box().get_boundary_points().first[2],
                thickness - 5,
                1e-13);
  }

  // Full model: four quadrants, the symmetry edges become shared.
  {
    SquareCupToolParameters full = parameters;
    full.full_model              = true;
    const auto full_tools        = build_square_cup_tools(full, thickness);
    check_true("full model: 48, 40, 16 patches",
               full_tools[0].n_patches() == 48
                 && full_tools[1].n_patches() == 40
                 && full_tools[2].n_patches() == 16);
    check_true("full model: free edges 12, 28, 32",
               count_free_edges(full_tools[0]) == 12
                 && count_free_edges(full_tools[1]) == 28
                 && count_free_edges(full_tools[2]) == 32);
    ProjectionResult r;
    full_tools[1].project(Point<3>(-36, -10, -20), r, 5.);
    check_close("full model: die wall in the third quadrant, normal x",
                r.normal[0],
                1.,
                1e-14);
    check_close("full model: gap there", r.gap, 1., 1e-12);
    check_junctions(full_tools[0]);
  }

  // Parameters: defaults, a changed value, an inconsistent set.
  {
    dealii::ParameterHandler prm;
    SquareCupToolParameters::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Tools\n set Model = full\n subsection Punch\n"
      "  set Profile radius = 6\n end\nend\n");
    SquareCupToolParameters parsed;
    parsed.parse_parameters(prm);
    check_true("parameters: Model = full", parsed.full_model);
    check_close("parameters: Punch/Profile radius",
                parsed.punch_profile_radius,
                6.,
                0.);
    check_close("parameters: default Die/Opening half width",
                parsed.die_opening_half_width,
                37.,
                0.);
    check_close("parameters: default Die/Shoulder radius",
                parsed.die_shoulder_radius,
                8.,
                0.);
    check_close("parameters: default Blank holder/Outer half width",
                parsed.blank_holder_outer_half_width,
                100.,
                0.);

    prm.parse_input_from_string("subsection Tools\n subsection Punch\n set "
                                "Plan corner radius = 5\n end\nend\n");
    std::string message;
    try
    {
      parsed.parse_parameters(prm);
    }
    catch (const deepdraw::InputError &error)
    {
      message = error.what();
    }
    std::cout << "  message: " << message << std::endl;
    check_true("parameters: plan corner radius below profile radius rejected, "
               "naming both",
               message.find("Punch/Plan corner radius (5)") != std::string::npos
                 && message.find("Punch/Profile radius (6)")
                      != std::string::npos);
  }
  return summary();
}
