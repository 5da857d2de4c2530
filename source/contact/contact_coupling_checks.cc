// The checks that no tool passed through the sheet (doc/decisions.md D56):
// a converged contact state says nothing about nodes the search did not
// find, so the start, the tool motion of each increment and the side of
// every node after it are checked separately.
#include <deepdraw/contact/contact_coupling.h>
#include <deepdraw/io/input_error.h>
#include <iomanip>
#include <sstream>

namespace deepdraw
{
  namespace contact
  {
    namespace
    {
      std::string
      format_point(const Point<3> &x)
      {
        std::ostringstream text;
        text << std::setprecision(4) << "(" << x[0] << ", " << x[1] << ", "
             << x[2] << ")";
        return text.str();
      }

      std::string
      format_length(const double length)
      {
        std::ostringstream text;
        text << std::setprecision(4) << length << " mm";
        return text.str();
      }

      // Outward normal of the flat blank's face a tool acts on.
      Tensor<1, 3>
      sheet_face_normal(const unsigned int sheet_face)
      {
        Tensor<1, 3> normal;
        normal[2] = sheet_face == 5 ? 1. : -1.;
        return normal;
      }
    } // namespace


    void
    ContactCoupling::check_initial_placement(
      const std::vector<Point<3>> &positions,
      const double                 sheet_thickness,
      const double                 load,
      const std::vector<bool>     &tools) const
    {
      const double     depth_limit = 0.5 * sheet_thickness;
      std::vector<int> facing(definitions.size(), 0);
      std::vector<int> turned_away(definitions.size(), 0);
      const auto       checked
        = [&](const unsigned int k) { return tools.empty() || tools[k]; };
      std::ostringstream at_load;
      at_load << std::setprecision(6) << load;
      for (const Pair &pair : pairs)
      {
        if (!checked(pair.tool))
          continue;
        geometry::ProjectionResult projection;
        if (!tool_list[pair.tool].project(positions[pair.vertex],
                                          projection,
                                          search_distance)
            || projection.on_edge)
          continue;
        const ToolDefinition &tool = definitions[pair.tool];
        if (projection.gap < -depth_limit)
          throw InputError(
            "Contact/Tool " + std::to_string(pair.tool + 1) + " ('" + tool.name
            + "'): the sheet node at " + format_point(positions[pair.vertex])
            + " starts " + format_length(-projection.gap)
            + " inside the tool at load " + at_load.str()
            + ", more than half the sheet thickness; place the tool outside "
              "the blank (Translation at t = "
            + at_load.str() + ")");
        const double alignment
          = projection.normal * sheet_face_normal(tool.sheet_face);
        if (alignment < -0.5)
          ++facing[pair.tool];
        else if (alignment > 0.5)
          ++turned_away[pair.tool];
      }
      for (unsigned int k = 0; k < definitions.size(); ++k)
        if (checked(k) && turned_away[k] > facing[k])
          throw InputError(
            "Contact/Tool " + std::to_string(k + 1) + " ('"
            + definitions[k].name
            + "'): the tool's normal points away from the sheet's "
            + (definitions[k].sheet_face == 5 ? "top" : "bottom")
            + " surface at " + std::to_string(turned_away[k]) + " of "
            + std::to_string(turned_away[k] + facing[k])
            + " nodes facing it; reverse the patches' orientation "
              "(doc/tool_files.md) or choose the other Sheet surface");
    }


    std::string
    ContactCoupling::check_tool_motion(const double old_load,
                                       const double new_load) const
    {
      for (unsigned int k = 0; k < definitions.size(); ++k)
        if (motions[k].takes_part && !motions[k].force_controlled)
        {
          const double motion = (prescribed_translation(k, new_load)
                                 - prescribed_translation(k, old_load))
                                  .norm();
          if (motion > search_distance)
            return "tool '" + definitions[k].name + "' moves "
                   + format_length(motion)
                   + " within the increment, more than Contact/Search "
                     "distance = "
                   + format_length(search_distance);
        }
      return "";
    }


    std::string
    ContactCoupling::check_tool_motion(const double          old_load,
                                       const double          new_load,
                                       const Vector<double> &solution) const
    {
      for (unsigned int k = 0; k < definitions.size(); ++k)
        if (position_dof[k] != numbers::invalid_dof_index)
        {
          const double motion
            = std::abs(solution[position_dof[k]] - position_at_start[k]);
          if (motion > search_distance)
            return std::string(motions[k].force_controlled ? "force-controlled"
                                                           : "spring-backed")
                   + " tool '" + definitions[k].name + "' moved "
                   + format_length(motion)
                   + " within the increment, more than Contact/Search "
                     "distance = "
                   + format_length(search_distance);
        }
      return check_tool_motion(old_load, new_load);
    }


    std::string
    ContactCoupling::check_tool_sides(const std::vector<Point<3>> &positions,
                                      const Vector<double>        &solution,
                                      const double sheet_thickness) const
    {
      for (const Pair &pair : pairs)
      {
        Point<3> x = positions[pair.vertex];
        for (unsigned int c = 0; c < 3; ++c)
          x[c] += solution[pair.u_dofs[c]];
        geometry::ProjectionResult projection;
        if (tool_list[pair.tool].project(x, projection, 2. * search_distance)
            && !projection.on_edge && projection.gap < -0.5 * sheet_thickness)
          return "a sheet node ended the increment at " + format_point(x) + ", "
                 + format_length(-projection.gap) + " inside tool '"
                 + definitions[pair.tool].name + "'";
      }
      return "";
    }
  } // namespace contact
} // namespace deepdraw
