#include <cmath>
#include <deepdraw/geometry/bezier_shapes.h>
#include <deepdraw/geometry/square_cup_tools.h>
#include <deepdraw/io/input_error.h>
#include <sstream>

namespace deepdraw::geometry
{
  namespace
  {
    using dealii::Point;
    using Vector = dealii::Tensor<1, 3>;

    Vector
    vector(const double x, const double y, const double z)
    {
      return Point<3>(x, y, z);
    }

    const Vector e_x = vector(1., 0., 0.);
    const Vector e_y = vector(0., 1., 0.);
    const Vector e_z = vector(0., 0., 1.);
    const double s45 = std::sqrt(0.5);

    // Patches of one quadrant (x >= 0, y >= 0) of a tool, each oriented
    // towards the sheet.
    using Patches = std::vector<BezierPatch>;

    void
    add(Patches &patches, const BezierPatch &patch, const Vector &towards_sheet)
    {
      patches.push_back(oriented_towards(patch, towards_sheet));
    }

    // Flat region at height z between a rounded-square hole (half-width
    // inner, plan corner radius r around (c, c), c = inner - r) and the
    // square of half-width outer: a strip along each side and the corner
    // split on the diagonal into two ruled patches (45-degree arc to a
    // straight outer edge), so that no patch corner has a 180-degree angle.
    void
    add_flat_ring(Patches      &patches,
                  const double  inner,
                  const double  r,
                  const double  outer,
                  const double  z,
                  const Vector &towards_sheet)
    {
      const double   c = inner - r;
      const Point<3> center(c, c, z);
      // c = 0: a round hole, no straight sides (the cylindrical cup, D76).
      if (c > 0.)
        add(patches,
            ruled_patch(
              straight_segment(Point<3>(inner, 0, z), Point<3>(outer, 0, z)),
              straight_segment(Point<3>(inner, c, z), Point<3>(outer, c, z))),
            towards_sheet);
      const RationalCurve lower = circular_arc(center, r * e_x, e_z, M_PI / 4);
      add(patches,
          ruled_patch(lower,
                      straight_segment(Point<3>(outer, c, z),
                                       Point<3>(outer, outer, z),
                                       lower.weights)),
          towards_sheet);
      const RationalCurve upper
        = circular_arc(center, r * vector(s45, s45, 0.), e_z, M_PI / 4);
      add(patches,
          ruled_patch(upper,
                      straight_segment(Point<3>(outer, outer, z),
                                       Point<3>(c, outer, z),
                                       upper.weights)),
          towards_sheet);
      if (c > 0.)
        add(patches,
            ruled_patch(
              straight_segment(Point<3>(0, inner, z), Point<3>(c, inner, z)),
              straight_segment(Point<3>(0, outer, z), Point<3>(c, outer, z))),
            towards_sheet);
    }

    // Flat rounded square of half-width c + r with plan corner radius r
    // around (c, c): a square, two side strips, and the quarter disc split
    // into three quadrilaterals (around an inner point) so that no patch is
    // degenerate.
    void
    add_flat_rounded_square(Patches      &patches,
                            const double  c,
                            const double  r,
                            const double  z,
                            const Vector &towards_sheet)
    {
      const auto segment = [](const Point<3> &a, const Point<3> &b)
      { return straight_segment(a, b); };
      // c = 0: the quarter disc alone (a round punch face, D76).
      if (c > 0.)
      {
        add(patches,
            ruled_patch(segment(Point<3>(0, 0, z), Point<3>(c, 0, z)),
                        segment(Point<3>(0, c, z), Point<3>(c, c, z))),
            towards_sheet);
        add(patches,
            ruled_patch(segment(Point<3>(c, 0, z), Point<3>(c + r, 0, z)),
                        segment(Point<3>(c, c, z), Point<3>(c + r, c, z))),
            towards_sheet);
        add(patches,
            ruled_patch(segment(Point<3>(0, c, z), Point<3>(c, c, z)),
                        segment(Point<3>(0, c + r, z), Point<3>(c, c + r, z))),
            towards_sheet);
      }
      const Point<3> center(c, c, z);
      const Point<3> half_x = center + 0.5 * r * e_x;
      const Point<3> half_y = center + 0.5 * r * e_y;
      const Point<3> inner  = center + 0.45 * r * vector(1., 1., 0.);
      add(patches,
          ruled_patch(segment(center, half_x), segment(half_y, inner)),
          towards_sheet);
      const RationalCurve lower = circular_arc(center, r * e_x, e_z, M_PI / 4);
      add(patches,
          ruled_patch(lower, straight_segment(half_x, inner, lower.weights)),
          towards_sheet);
      const RationalCurve upper
        = circular_arc(center, r * vector(s45, s45, 0.), e_z, M_PI / 4);
      add(patches,
          ruled_patch(upper, straight_segment(inner, half_y, upper.weights)),
          towards_sheet);
    }

    // Quarter-circle fillet around a rounded-square plan contour: its tube
    // centre runs at half-width tube_half_width (plan corner radius
    // tube_corner_radius around (c, c)) at height tube_z; the profile arc
    // starts in direction start (±e_z) and turns by 90 degrees towards
    // `turn` · (outward horizontal) with turn = ±1. Sides along x = const,
    // the torus corner, the side along y = const.
    void
    add_fillet(Patches     &patches,
               const double c,
               const double tube_corner_radius,
               const double tube_z,
               const double radius,
               const double start_sign,
               const double turn_sign)
    {
      const double tube_half_width = c + tube_corner_radius;
      // The profile turns from start_sign e_z towards turn_sign e_x (plane
      // y = const) or turn_sign e_y (plane x = const): the rotation axis a
      // satisfies a × (start_sign e_z) = turn_sign e_x (resp. e_y).
      const Vector   axis_xz = start_sign * turn_sign * e_y;
      const Vector   axis_yz = -start_sign * turn_sign * e_x;
      const double   s       = start_sign;
      const double   t       = turn_sign;
      const Point<3> center_x(tube_half_width, 0, tube_z);
      // c = 0: the torus corner alone (a round contour, D76).
      if (c > 0.)
        add(patches,
            extruded_patch(
              circular_arc(center_x, radius * s * e_z, axis_xz, M_PI / 2),
              c * e_y),
            vector(t, 0., s));
      const Point<3> center_corner(tube_half_width, c, tube_z);
      add(patches,
          revolved_patch(
            circular_arc(center_corner, radius * s * e_z, axis_xz, M_PI / 2),
            Point<3>(c, c, 0.),
            e_z,
            M_PI / 2),
          vector(t * s45, t * s45, s));
      const Point<3> center_y(0, tube_half_width, tube_z);
      if (c > 0.)
        add(patches,
            extruded_patch(
              circular_arc(center_y, radius * s * e_z, axis_yz, M_PI / 2),
              c * e_x),
            vector(0., t, s));
    }

    // Vertical wall of a rounded square (half-width c + r, plan corner
    // radius r) from z0 to z1; normal outwards (sign +1) or inwards (-1).
    void
    add_wall(Patches     &patches,
             const double c,
             const double r,
             const double z0,
             const double z1,
             const double outward_sign)
    {
      const double w = c + r;
      const double o = outward_sign;
      // c = 0: the cylinder alone (D76).
      if (c > 0.)
        add(
          patches,
          ruled_patch(straight_segment(Point<3>(w, 0, z0), Point<3>(w, c, z0)),
                      straight_segment(Point<3>(w, 0, z1), Point<3>(w, c, z1))),
          o * e_x);
      add(
        patches,
        extruded_patch(circular_arc(Point<3>(c, c, z0), r * e_x, e_z, M_PI / 2),
                       (z1 - z0) * e_z),
        vector(o * s45, o * s45, 0.));
      if (c > 0.)
        add(
          patches,
          ruled_patch(straight_segment(Point<3>(0, w, z0), Point<3>(c, w, z0)),
                      straight_segment(Point<3>(0, w, z1), Point<3>(c, w, z1))),
          o * e_y);
    }

    // The quarter patches, or their four mirror images for the full model;
    // quarter-model edges on x = 0 or y = 0 are symmetry edges.
    RigidTool
    assemble(const std::string &name,
             const Patches     &quarter,
             const bool         full_model)
    {
      RigidTool tool(name);
      if (!full_model)
      {
        for (const BezierPatch &patch : quarter)
        {
          RigidTool::EdgeKinds edges;
          for (unsigned int e = 0; e < 4; ++e)
          {
            bool on_x0 = true, on_y0 = true;
            for (unsigned int m = 0; m <= 8; ++m)
            {
              const double   t = m / 8.;
              const Point<3> x
                = (e < 2) ? patch.value(e, t) : patch.value(t, e - 2);
              const double tolerance = 1e-12 * patch.length_scale();
              on_x0                  = on_x0 && std::abs(x[0]) <= tolerance;
              on_y0                  = on_y0 && std::abs(x[1]) <= tolerance;
            }
            edges[e]
              = (on_x0 || on_y0) ? EdgeKind::symmetry : EdgeKind::automatic;
          }
          tool.add_patch(patch, edges);
        }
        return tool;
      }
      for (const double sx : {1., -1.})
        for (const double sy : {1., -1.})
          for (const BezierPatch &patch : quarter)
          {
            std::vector<Point<3>> points = patch.control_points();
            for (Point<3> &x : points)
            {
              x[0] *= sx;
              x[1] *= sy;
            }
            const BezierPatch mirrored(patch.degree_u(),
                                       patch.degree_v(),
                                       points,
                                       patch.weights());
            // A single reflection turns the normal inside out.
            tool.add_patch(sx * sy > 0 ? mirrored : mirrored.reversed_u());
          }
      return tool;
    }

    void
    require(const bool condition, const std::string &message)
    {
      if (!condition)
        throw InputError("Parameters in subsection Tools: " + message);
    }

    std::string
    value(const double x)
    {
      std::ostringstream stream;
      stream << x;
      return stream.str();
    }
  } // namespace


  void
  SquareCupToolParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Double;
    const SquareCupToolParameters defaults;
    // Every dimension at most 10 m (D50).
    constexpr double max_dimension = 1e4;
    prm.enter_subsection("Tools");
    {
      prm.declare_entry(
        "Model",
        "quarter",
        dealii::Patterns::Selection("quarter|full"),
        "quarter: x >= 0, y >= 0 with symmetry planes x = 0 and "
        "y = 0; full: all four quadrants.");
      prm.enter_subsection("Punch");
      {
        prm.declare_entry("Half width",
                          value(defaults.punch_half_width),
                          Double(0., max_dimension),
                          "Half of the punch width in plan view (mm).");
        prm.declare_entry("Plan corner radius",
                          value(defaults.punch_corner_radius),
                          Double(0., max_dimension),
                          "Radius of the punch corners in plan view (mm); "
                          "equal to Half width: a round punch (cylindrical "
                          "cup).");
        prm.declare_entry("Profile radius",
                          value(defaults.punch_profile_radius),
                          Double(0., max_dimension),
                          "Nose radius between punch face and wall (mm).");
        prm.declare_entry("Height",
                          value(defaults.punch_height),
                          Double(0., max_dimension),
                          "Height of the punch walls above its face (mm).");
        prm.declare_entry("Initial gap",
                          value(defaults.punch_initial_gap),
                          Double(0., max_dimension),
                          "Distance of the punch face above the sheet's top "
                          "face at the start (mm).");
      }
      prm.leave_subsection();
      prm.enter_subsection("Die");
      {
        prm.declare_entry("Opening half width",
                          value(defaults.die_opening_half_width),
                          Double(0., max_dimension),
                          "Half of the die opening in plan view (mm).");
        prm.declare_entry("Plan corner radius",
                          value(defaults.die_corner_radius),
                          Double(0., max_dimension),
                          "Radius of the opening's corners in plan view "
                          "(mm); equal to Opening half width: a round "
                          "opening.");
        prm.declare_entry("Shoulder radius",
                          value(defaults.die_shoulder_radius),
                          Double(0., max_dimension),
                          "Radius between die face and die wall (mm).");
        prm.declare_entry(
          "Depth",
          value(defaults.die_depth),
          Double(0., max_dimension),
          "Depth of the die wall's lower edge below the die face (mm).");
        prm.declare_entry(
          "Outer half width",
          value(defaults.die_outer_half_width),
          Double(0., max_dimension),
          "Half width of the die face's square outer edge (mm).");
      }
      prm.leave_subsection();
      prm.enter_subsection("Blank holder");
      {
        prm.declare_entry(
          "Outer half width",
          value(defaults.blank_holder_outer_half_width),
          Double(0., max_dimension),
          "Half width of the blank holder's square outer edge (mm); its inner "
          "contour is the die opening + 2 x shoulder radius.");
        prm.declare_entry("Initial gap",
                          value(defaults.blank_holder_initial_gap),
                          Double(0., max_dimension),
                          "Distance of the blank holder above the sheet's top "
                          "face at the start (mm).");
      }
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }


  void
  SquareCupToolParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Tools");
    {
      full_model = prm.get("Model") == "full";
      prm.enter_subsection("Punch");
      punch_half_width     = prm.get_double("Half width");
      punch_corner_radius  = prm.get_double("Plan corner radius");
      punch_profile_radius = prm.get_double("Profile radius");
      punch_height         = prm.get_double("Height");
      punch_initial_gap    = prm.get_double("Initial gap");
      prm.leave_subsection();
      prm.enter_subsection("Die");
      die_opening_half_width = prm.get_double("Opening half width");
      die_corner_radius      = prm.get_double("Plan corner radius");
      die_shoulder_radius    = prm.get_double("Shoulder radius");
      die_depth              = prm.get_double("Depth");
      die_outer_half_width   = prm.get_double("Outer half width");
      prm.leave_subsection();
      prm.enter_subsection("Blank holder");
      blank_holder_outer_half_width = prm.get_double("Outer half width");
      blank_holder_initial_gap      = prm.get_double("Initial gap");
      prm.leave_subsection();
    }
    prm.leave_subsection();
    check();
  }


  void
  SquareCupToolParameters::check() const
  {
    require(punch_profile_radius > 0.,
            "Punch/Profile radius (" + value(punch_profile_radius)
              + ") must be positive");
    require(punch_corner_radius > punch_profile_radius,
            "Punch/Plan corner radius (" + value(punch_corner_radius)
              + ") must exceed Punch/Profile radius ("
              + value(punch_profile_radius) + ")");
    // Equal: a round punch (the cylindrical cup, D76).
    require(punch_half_width >= punch_corner_radius,
            "Punch/Half width (" + value(punch_half_width)
              + ") must be at least Punch/Plan corner radius ("
              + value(punch_corner_radius) + ")");
    require(punch_height > punch_profile_radius,
            "Punch/Height (" + value(punch_height)
              + ") must exceed Punch/Profile radius ("
              + value(punch_profile_radius) + ")");
    require(die_shoulder_radius > 0.,
            "Die/Shoulder radius (" + value(die_shoulder_radius)
              + ") must be positive");
    require(die_corner_radius > 0.,
            "Die/Plan corner radius (" + value(die_corner_radius)
              + ") must be positive");
    require(die_opening_half_width >= die_corner_radius,
            "Die/Opening half width (" + value(die_opening_half_width)
              + ") must be at least Die/Plan corner radius ("
              + value(die_corner_radius) + ")");
    require(die_opening_half_width > punch_half_width,
            "Die/Opening half width (" + value(die_opening_half_width)
              + ") must exceed Punch/Half width (" + value(punch_half_width)
              + ")");
    require(die_depth > die_shoulder_radius,
            "Die/Depth (" + value(die_depth)
              + ") must exceed Die/Shoulder radius ("
              + value(die_shoulder_radius) + ")");
    const double flat_edge = die_opening_half_width + die_shoulder_radius;
    require(die_outer_half_width > flat_edge,
            "Die/Outer half width (" + value(die_outer_half_width)
              + ") must exceed Die/Opening half width + Die/Shoulder radius ("
              + value(flat_edge) + ")");
    require(blank_holder_outer_half_width > flat_edge,
            "Blank holder/Outer half width ("
              + value(blank_holder_outer_half_width)
              + ") must exceed Die/Opening half width + Die/Shoulder radius ("
              + value(flat_edge) + ")");
    require(punch_initial_gap >= 0. && blank_holder_initial_gap >= 0.,
            "initial gaps must not be negative");
  }


  std::vector<RigidTool>
  build_square_cup_tools(const SquareCupToolParameters &parameters,
                         const double                   sheet_thickness)
  {
    parameters.check();
    if (!(sheet_thickness > 0.))
      throw InputError("The sheet thickness (" + value(sheet_thickness)
                       + ") must be positive");
    const SquareCupToolParameters &P = parameters;

    // Punch: face at z0, nose tube centre at z0 + rp, walls up to z0 + height.
    Patches punch;
    {
      const double z0 = sheet_thickness + P.punch_initial_gap;
      const double rp = P.punch_profile_radius;
      const double c  = P.punch_half_width - P.punch_corner_radius;
      const double ri = P.punch_corner_radius - rp; // plan radius of the face
      add_flat_rounded_square(punch, c, ri, z0, -e_z);
      add_fillet(punch, c, ri, z0 + rp, rp, -1., +1.);
      add_wall(punch,
               c,
               P.punch_corner_radius,
               z0 + rp,
               z0 + P.punch_height,
               +1.);
    }

    // Die: face at z = 0 outside the opening + shoulder, shoulder tube
    // centre at z = -rs, wall down to -depth.
    Patches die;
    {
      const double rs = P.die_shoulder_radius;
      const double c  = P.die_opening_half_width - P.die_corner_radius;
      add_flat_ring(die,
                    P.die_opening_half_width + rs,
                    P.die_corner_radius + rs,
                    P.die_outer_half_width,
                    0.,
                    e_z);
      add_fillet(die, c, P.die_corner_radius + rs, -rs, rs, +1., -1.);
      add_wall(die, c, P.die_corner_radius, -rs, -P.die_depth, -1.);
    }

    // Blank holder: flat ring on the flange, inner contour over the start
    // of the die shoulder.
    Patches holder;
    add_flat_ring(holder,
                  P.die_opening_half_width + P.die_shoulder_radius,
                  P.die_corner_radius + P.die_shoulder_radius,
                  P.blank_holder_outer_half_width,
                  sheet_thickness + P.blank_holder_initial_gap,
                  -e_z);

    std::vector<RigidTool> tools;
    tools.push_back(assemble("punch", punch, P.full_model));
    tools.push_back(assemble("die", die, P.full_model));
    tools.push_back(assemble("blank holder", holder, P.full_model));
    return tools;
  }
} // namespace deepdraw::geometry
