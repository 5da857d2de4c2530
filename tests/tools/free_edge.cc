// Free edges: a point beside the blank holder's inner contour (its foot
// clamped onto that free edge) is flagged; points under the holder, on the
// symmetry planes, or sliding across shared edges are not.
#include "test_utilities.h"

#include <cmath>
#include <deepdraw/geometry/bezier_shapes.h>
#include <deepdraw/geometry/square_cup_tools.h>

using namespace deepdraw::geometry;
using namespace deepdraw_test;
using dealii::Point;

int
main()
{
  const double thickness = 0.81;
  for (const bool full_model : {false, true})
  {
    SquareCupToolParameters parameters;
    parameters.full_model    = full_model;
    const auto        tools  = build_square_cup_tools(parameters, thickness);
    const RigidTool  &holder = tools[2];
    const RigidTool  &punch  = tools[0];
    const RigidTool  &die    = tools[1];
    const std::string model  = full_model ? "full model: " : "quarter model: ";
    ProjectionResult  r;
    const double      z = thickness - 0.05; // sheet top, 0.05 below the holder

    // Beside the straight part of the inner contour (x = 45): foot at the
    // edge, gap measured along the normal, flagged.
    check_true(model + "point at x = 40 projects",
               holder.project(Point<3>(40, 10, z), r, 10.));
    check_true(
      model + "point at x = 40 (inside the holder opening) is on a free edge",
      r.on_free_edge);
    check_close(model + "its foot x (clamped to the contour x = 45)",
                r.foot[0],
                45.,
                1e-12);
    check_close(model + "its distance",
                r.distance,
                std::hypot(5., 0.05),
                1e-12);
    // Beside the corner arc (radius 20 about (25, 25)).
    holder.project(Point<3>(35, 35, z), r, 20.);
    check_true(model
                 + "point at (35, 35) inside the corner arc is on a free edge",
               r.on_free_edge);
    check_close(model + "its foot on the arc, radius about (25, 25)",
                std::hypot(r.foot[0] - 25, r.foot[1] - 25),
                20.,
                1e-12);
    // Just beyond the contour (1e-6): still flagged; just inside: not.
    holder.project(Point<3>(45 - 1e-6, 10, z), r, 10.);
    check_true(model + "1e-6 beyond the contour: free edge", r.on_free_edge);
    holder.project(Point<3>(45 + 1e-6, 10, z), r, 10.);
    check_true(model + "1e-6 under the holder: in contact range, not free",
               !r.on_free_edge);
    check_close(model + "its gap", r.gap, 0.05, 1e-13);

    // Under the holder: no flag, across the diagonal junction too.
    for (const Point<3> &x : {Point<3>(60, 10, z),
                              Point<3>(60, 60, z),
                              Point<3>(50, 50, z),
                              Point<3>(70, 25, z),
                              Point<3>(25, 70, z)})
    {
      holder.project(x, r, 10.);
      check_true(model + "under the holder: not free, gap 0.05",
                 !r.on_free_edge && std::abs(r.gap - 0.05) < 1e-13);
    }
    // On the symmetry planes (exactly, and 1e-12 outside the quarter).
    for (const Point<3> &x :
         {Point<3>(60, 0, z), Point<3>(0, 60, z), Point<3>(60, -1e-12, z)})
    {
      holder.project(x, r, 10.);
      check_true(model + "on a symmetry plane: not free", !r.on_free_edge);
    }
    // Punch face and nose: shared edges never flag.
    bool punch_flag = false, die_flag = false;
    for (double x = 0; x <= 34.; x += 0.25)
    {
      punch.project(Point<3>(x, 10, thickness - 0.1), r, 10.);
      punch_flag = punch_flag || r.on_free_edge;
      die.project(Point<3>(x + 10, 10, 0.1), r, 10.);
      die_flag = die_flag || r.on_free_edge;
    }
    check_true(model + "sweep under the punch (face → nose): no free edge",
               !punch_flag);
    check_true(
      model + "sweep over the die (opening → shoulder → face): no free edge",
      !die_flag);
    // Beyond the die's outer edge: flagged.
    die.project(Point<3>(101, 10, 0.1), r, 10.);
    check_true(model + "beyond the die's outer edge: free edge",
               r.on_free_edge);
  }

  // Explicitly declared kinds override the automatic classification.
  {
    const BezierPatch square
      = ruled_patch(straight_segment(Point<3>(0, 0, 0), Point<3>(1, 0, 0)),
                    straight_segment(Point<3>(0, 1, 0), Point<3>(1, 1, 0)));
    RigidTool tool("square");
    tool.add_patch(square,
                   {{EdgeKind::shared,
                     EdgeKind::free,
                     EdgeKind::symmetry,
                     EdgeKind::automatic}});
    ProjectionResult r;
    tool.project(Point<3>(-0.5, 0.5, 0.2), r, 2.);
    check_true("declared shared edge: clamped but not free",
               r.on_edge && !r.on_free_edge);
    tool.project(Point<3>(1.5, 0.5, 0.2), r, 2.);
    check_true("declared free edge: flagged", r.on_free_edge);
    tool.project(Point<3>(0.5, 1.5, 0.2), r, 2.);
    check_true("automatic edge without neighbour: flagged", r.on_free_edge);
    check_true("search distance: false when no patch is near",
               !tool.project(Point<3>(0.5, 0.5, 3.), r, 2.));
  }
  return summary();
}
