#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/postprocess/process_tables.h>
#include <sstream>

namespace deepdraw
{
  namespace postprocess
  {
    void
    ProcessTables::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Process tables");
      prm.declare_entry("Punch tool",
                        "punch",
                        Patterns::Anything(),
                        "Name of the tool (Contact/Tool N/Name) whose force "
                        "along its motion is punch_force_N in "
                        "punch_force.csv. The default 'punch' is used if a "
                        "tool has that name (no punch_force.csv otherwise); "
                        "any other name must exist.");
      prm.declare_entry("Blank holder tool",
                        "",
                        Patterns::Anything(),
                        "Name of the force-controlled tool whose force and "
                        "position are holder_force_N and holder_z_mm in "
                        "punch_force.csv; empty: the first force-controlled "
                        "tool.");
      prm.declare_entry("Draw-in points",
                        "DX: x axis; DY: y axis; DD: diagonal",
                        Patterns::Anything(),
                        "Points of the blank edge whose draw-in draw_in.csv "
                        "reports, 'NAME: X, Y; ...' with X, Y the initial "
                        "in-plane position in mm or the words length, "
                        "width (Geometry), or 'NAME: x axis', 'y axis', "
                        "'diagonal': where the ray from the origin along x, "
                        "y or x = y leaves the blank. The draw-in is the "
                        "decrease of the in-plane distance of the "
                        "mid-surface point there to the cup axis x = y = 0; "
                        "column NAME_mm.");
      prm.leave_subsection();
    }


    void
    ProcessTables::parse_parameters(ParameterHandler           &prm,
                                    const blank::BlankGeometry &geometry)
    {
      prm.enter_subsection("Process tables");
      punch_name               = Utilities::trim(prm.get("Punch tool"));
      holder_name              = Utilities::trim(prm.get("Blank holder tool"));
      const std::string points = prm.get("Draw-in points");
      prm.leave_subsection();

      const std::string where = "Process tables/Draw-in points: ";
      const auto        coordinate
        = [&](const std::string &text, const std::string &entry)
      {
        const std::string word = Utilities::trim(text);
        if (word == "length")
          return geometry.length;
        if (word == "width")
          return geometry.width;
        std::size_t used  = 0;
        double      value = 0.;
        try
        {
          value = std::stod(word, &used);
        }
        catch (const std::exception &)
        {
          used = 0;
        }
        if (used == 0 || used != word.size() || !std::isfinite(value))
          throw InputError(where + "in '" + entry + "', '" + word
                           + "' is not a number, 'length' or 'width'");
        return value;
      };
      draw_in_points.clear();
      std::istringstream list(points);
      std::string        entry;
      while (std::getline(list, entry, ';'))
      {
        entry = Utilities::trim(entry);
        if (entry.empty())
          continue;
        const auto colon = entry.find(':');
        const auto comma
          = entry.find(',', colon == std::string::npos ? 0 : colon);
        DrawInPoint point;
        point.name
          = Utilities::trim(entry.substr(0, std::min(colon, entry.size())));
        const std::string where_on
          = colon == std::string::npos
              ? ""
              : Utilities::trim(entry.substr(colon + 1));
        const std::pair<const char *, Tensor<1, 2>> rays[]
          = {{"x axis", Tensor<1, 2>({1., 0.})},
             {"y axis", Tensor<1, 2>({0., 1.})},
             {"diagonal", Tensor<1, 2>({std::sqrt(0.5), std::sqrt(0.5)})}};
        for (const auto &[word, direction] : rays)
          if (where_on == word)
            point.ray = direction;
        if (!point.ray)
        {
          if (colon == std::string::npos || comma == std::string::npos
              || point.name.empty())
            throw InputError(where + "'" + entry
                             + "' is not of the form 'NAME: X, Y' or 'NAME: "
                               "x axis' ('y axis', 'diagonal')");
          point.requested
            = Point<2>(coordinate(entry.substr(colon + 1, comma - colon - 1),
                                  entry),
                       coordinate(entry.substr(comma + 1), entry));
        }
        draw_in_points.push_back(point);
      }
    }


    void
    ProcessTables::set_up(const contact::ContactCoupling &contact,
                          const double                    final_load,
                          const blank::SheetThickness    &sheet,
                          const std::vector<Point<3>>    &initial_vertices)
    {
      tables_wanted = contact.active();
      if (!tables_wanted)
        return;
      const std::vector<contact::ToolDefinition> &tools
        = contact.tool_definitions();
      for (unsigned int k = 0; k < tools.size(); ++k)
      {
        if (punch_tool == numbers::invalid_unsigned_int
            && tools[k].name == punch_name)
          punch_tool = k;
        if (holder_tool == numbers::invalid_unsigned_int
            && tools[k].force_controlled
            && (holder_name.empty() || tools[k].name == holder_name))
          holder_tool = k;
      }
      if (punch_tool == numbers::invalid_unsigned_int && punch_name != "punch"
          && !punch_name.empty())
        throw InputError("Process tables/Punch tool: no tool is named '"
                         + punch_name + "'");
      if (holder_tool == numbers::invalid_unsigned_int && !holder_name.empty())
        throw InputError("Process tables/Blank holder tool: no "
                         "force-controlled tool is named '"
                         + holder_name + "'");
      if (punch_tool != numbers::invalid_unsigned_int)
      {
        // Direction of the punch motion over the whole run; a punch that
        // does not move is taken to push along -z.
        const contact::ToolDefinition &punch = tools[punch_tool];
        punch_direction
          = punch.force_controlled
              ? punch.axis
              : contact.prescribed_translation(punch_tool, final_load)
                  - contact.prescribed_translation(punch_tool, 0.);
        if (punch_direction.norm() > 0.)
          punch_direction /= punch_direction.norm();
        else
          punch_direction = Tensor<1, 3>({0., 0., -1.});
      }
      for (DrawInPoint &point : draw_in_points)
      {
        if (point.ray)
        {
          // Where the ray leaves the sheet: the last crossing of a face edge.
          const std::vector<double> s = sheet.ray_crossings(*point.ray);
          if (s.empty())
            throw InputError("Process tables/Draw-in points: the ray of "
                             + point.name + " does not meet the blank");
          point.requested = Point<2>(s.back() * *point.ray);
        }
        const auto location = sheet.locate(point.requested);
        if (!location)
          throw InputError("Process tables/Draw-in points: " + point.name + " ("
                           + std::to_string(point.requested[0]) + ", "
                           + std::to_string(point.requested[1])
                           + ") is not on the blank");
        point.location       = *location;
        const Point<3> mid   = sheet.mid_surface(*location, initial_vertices);
        point.initial_radius = std::hypot(mid[0], mid[1]);
      }
    }


    const Tensor<1, 3> &
    ProcessTables::punch_motion() const
    {
      return punch_direction;
    }


    void
    ProcessTables::open(const std::string &directory, const bool append)
    {
      if (!tables_wanted)
        return;
      if (punch_tool != numbers::invalid_unsigned_int)
        punch_force_file.open(
          directory + "/punch_force.csv",
          {"punch_travel_mm", "punch_force_N", "holder_force_N", "holder_z_mm"},
          append);
      std::vector<std::string> columns = {"punch_travel_mm"};
      for (const DrawInPoint &point : draw_in_points)
        columns.push_back(point.name + "_mm");
      draw_in_file.open(directory + "/draw_in.csv", columns, append);
    }


    void
    ProcessTables::write(const double                    load,
                         const contact::ContactCoupling &contact,
                         const std::vector<Point<3>>    &vertices)
    {
      if (!tables_wanted)
        return;
      // Forces of the tools on the sheet, positive when the punch pushes
      // along its motion and the holder presses along its axis.
      const std::vector<Tensor<1, 3>> forces       = contact.tool_forces();
      double                          holder_force = 0., holder_z = 0.;
      if (holder_tool != numbers::invalid_unsigned_int)
      {
        holder_force
          = forces[holder_tool] * contact.tool_definitions()[holder_tool].axis;
        holder_z = contact.tools()[holder_tool].translation()[2];
      }
      if (punch_tool != numbers::invalid_unsigned_int)
        punch_force_file.add_row(
          {load, forces[punch_tool] * punch_direction, holder_force, holder_z});

      std::vector<double> row = {load};
      for (const DrawInPoint &point : draw_in_points)
      {
        const Point<3> mid
          = blank::SheetThickness::mid_surface(point.location, vertices);
        row.push_back(point.initial_radius - std::hypot(mid[0], mid[1]));
      }
      draw_in_file.add_row(row);
    }
  } // namespace postprocess
} // namespace deepdraw
