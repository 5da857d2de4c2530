// The NUMISHEET'93 square-cup tools (doc/results.md) built from their
// dimensions as exact rational Bézier patches (planes, cylinders, tori).
//
// Coordinates: blank bottom surface z = 0, top z = t. The die lies below the
// sheet (flat top face z = 0, opening half-width 37, shoulder radius 8, wall
// going down), the punch above it (flat face z = t + gap, moving in -z), the
// blank holder on the flange (flat face z = t + gap, inner contour = die
// opening + 2 × shoulder radius, a free edge). The quarter model covers
// x >= 0, y >= 0; its edges on x = 0 and y = 0 are symmetry edges.
// Every normal points towards the sheet. A plan corner radius equal to the
// half width makes the punch or the die opening round (the cylindrical
// cup, D76): the straight sides vanish and their patches are left out.
#ifndef deepdraw_geometry_square_cup_tools_h
#define deepdraw_geometry_square_cup_tools_h

#include <deal.II/base/parameter_handler.h>
#include <deepdraw/geometry/rigid_tool.h>
#include <vector>

namespace deepdraw::geometry
{
  // Dimensions in mm; parameters in "subsection Tools".
  struct SquareCupToolParameters
  {
    bool full_model = false;

    double punch_half_width     = 35.;
    double punch_corner_radius  = 10.; // plan view
    double punch_profile_radius = 8.;  // nose
    double punch_height         = 50.;
    double punch_initial_gap    = 0.; // above the sheet's top face

    double die_opening_half_width = 37.;
    double die_corner_radius      = 12.; // plan view
    double die_shoulder_radius    = 8.;
    double die_depth              = 50.; // wall bottom below the flat
    double die_outer_half_width   = 100.;

    double blank_holder_outer_half_width = 100.;
    double blank_holder_initial_gap      = 0.;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    // Reads and checks (InputError naming the parameter on inconsistent
    // dimensions).
    void
    parse_parameters(dealii::ParameterHandler &prm);
    void
    check() const;
  };

  // Returns {punch, die, blank holder} (names "punch", "die", "blank holder")
  // at their initial placement; their motion is the tool slots' business
  // (Contact/Tool N/Translation, or the force-controlled position), applied
  // with RigidTool::set_rigid_motion().
  std::vector<RigidTool>
  build_square_cup_tools(const SquareCupToolParameters &parameters,
                         double                         sheet_thickness);
} // namespace deepdraw::geometry

#endif
