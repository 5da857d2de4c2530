#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deepdraw/adaptivity/adaptivity_parameters.h>
#include <deepdraw/io/input_error.h>

namespace deepdraw
{
  namespace adaptivity
  {
    namespace
    {
      Point<3>
      parse_point(const std::string &text, const std::string &parameter)
      {
        std::vector<double> values;
        try
        {
          values
            = Utilities::string_to_double(Utilities::split_string_list(text));
        }
        catch (const std::exception &)
        {
          values.clear();
        }
        // Finite and within the range of any length of the model (D50).
        const bool finite
          = values.size() == 3
            && std::all_of(values.begin(),
                           values.end(),
                           [](const double x)
                           { return std::isfinite(x) && std::abs(x) <= 1e6; });
        if (!finite)
          throw InputError("Adaptivity/" + parameter
                           + ": three finite coordinates x, y, z (mm, at most "
                             "1e6 in magnitude) expected, got '"
                           + text + "'");
        return Point<3>(values[0], values[1], values[2]);
      }
    } // namespace


    void
    AdaptivityParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Adaptivity");
      prm.declare_entry("Enabled",
                        "false",
                        Patterns::Bool(),
                        "Refine the mesh between converged increments "
                        "(doc/user_guide.md, Adaptivity). Off: the mesh of "
                        "subsection Geometry throughout.");
      prm.declare_entry("Refinement interval",
                        "5",
                        Patterns::Integer(1, 100000),
                        "Refine after every this many converged increments; "
                        "each refinement is followed by a re-equilibration "
                        "at the same load.");
      prm.declare_entry("Maximum level",
                        "2",
                        Patterns::Integer(0, 10),
                        "Refinement level a cell may reach (the cells of "
                        "subsection Geometry are level 0; each refinement, "
                        "isotropic or not, adds one level).");
      prm.declare_entry("Maximum number of cells",
                        "100000",
                        Patterns::Integer(1),
                        "Cells selected by the indicator are refined, "
                        "largest indicator first, only while the active "
                        "cells stay at most this many.");
      prm.declare_entry("Indicator",
                        "plastic strain jump",
                        Patterns::Selection(
                          "plastic strain jump|tool curvature|tool curvature "
                          "or plastic strain jump|region"),
                        "Which cells are refined: 'plastic strain jump' "
                        "those whose cell-average equivalent plastic strain "
                        "differs from a face neighbour's by more than Jump "
                        "threshold; 'tool curvature' the columns through the "
                        "thickness under a curved part of a tool (within one "
                        "sheet thickness of it) whose in-plane size times "
                        "the tool's curvature exceeds Curvature threshold, "
                        "so before they bend; 'tool curvature or plastic "
                        "strain jump' the cells either selects; 'region' "
                        "those whose centre in "
                        "the initial configuration lies in the box Region "
                        "minimum..Region maximum (doc/theory.md §8.1).");
      prm.declare_entry("Jump threshold",
                        "0.02",
                        Patterns::Double(0., 10.),
                        "Indicator = plastic strain jump: the jump of the "
                        "equivalent plastic strain between neighbouring "
                        "cells above which both are refined (0 to 10).");
      prm.declare_entry("Curvature threshold",
                        "0.25",
                        Patterns::Double(0.001, 10.),
                        "Indicator = tool curvature: refine while a cell's "
                        "in-plane size h exceeds this fraction of the tool "
                        "radius R it lies on (h/R, 0.001 to 10; 0.25: four "
                        "elements per radius length).");
      prm.declare_entry("Region minimum",
                        "0, 0, 0",
                        Patterns::Anything(),
                        "Indicator = region: lower corner x, y, z (mm) of "
                        "the box, in the initial configuration.");
      prm.declare_entry("Region maximum",
                        "0, 0, 0",
                        Patterns::Anything(),
                        "Indicator = region: upper corner x, y, z (mm).");
      prm.declare_entry("Refinement",
                        "isotropic",
                        Patterns::Selection("isotropic|cut_z|in_plane"),
                        "How a selected cell is refined: into 8 children, "
                        "into 2 through the thickness (cut_z: more layers "
                        "where the sheet bends) or into 4 in the plane of "
                        "the sheet (in_plane: smaller elements along the "
                        "tool radii, same layers).");
      prm.declare_entry("Vertex placement",
                        "smooth",
                        Patterns::Selection("linear|smooth"),
                        "Where the vertices added by a refinement go: "
                        "'linear' at the Q1 interpolation of the coarse "
                        "vertices (on the chord of a bent edge), 'smooth' on "
                        "the cubic through the old vertices along each mesh "
                        "line (doc/theory.md §8, D87); vertices of cells "
                        "with a hanging vertex stay at the Q1 position. "
                        "With 'smooth', in_plane refinement by the plastic "
                        "strain jump refines whole through-thickness "
                        "columns (D89).");
      prm.declare_entry("History transfer",
                        "nearest",
                        Patterns::Selection("nearest|interpolated"),
                        "How the Gauss points of a refined cell get their "
                        "history: 'nearest' the state of the parent's "
                        "nearest Gauss point (D57), 'interpolated' the "
                        "interpolation of the parent's points, linear "
                        "between them along each direction (trilinear with "
                        "2 points through the thickness), returned to the "
                        "yield surface (D88, D202).");
      prm.leave_subsection();
    }


    void
    AdaptivityParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Adaptivity");
      enabled             = prm.get_bool("Enabled");
      interval            = prm.get_integer("Refinement interval");
      maximum_level       = prm.get_integer("Maximum level");
      maximum_cells       = prm.get_integer("Maximum number of cells");
      indicator           = prm.get("Indicator");
      jump_threshold      = prm.get_double("Jump threshold");
      curvature_threshold = prm.get_double("Curvature threshold");
      region_min = parse_point(prm.get("Region minimum"), "Region minimum");
      region_max = parse_point(prm.get("Region maximum"), "Region maximum");
      refinement = prm.get("Refinement");
      vertex_placement = prm.get("Vertex placement");
      history_transfer = prm.get("History transfer");
      prm.leave_subsection();
    }


    RefinementCase<3>
    AdaptivityParameters::refinement_case() const
    {
      if (refinement == "cut_z")
        return RefinementCase<3>::cut_z;
      if (refinement == "in_plane")
        return RefinementCase<3>::cut_xy;
      return RefinementCase<3>::isotropic_refinement;
    }
  } // namespace adaptivity
} // namespace deepdraw
