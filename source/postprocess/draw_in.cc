// Post-processor "draw-in": draw_in.csv (runs with tools), per converged
// load (and t = 0), the draw-in of points of the blank edge: the decrease
// of the in-plane distance of the mid-surface point there to the cup axis
// x = y = 0 (doc/user_guide.md §3.1).
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deepdraw/io/csv_file.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/postprocess/interface.h>
#include <deepdraw/postprocess/table_names.h>
#include <optional>
#include <sstream>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      const std::string where = "Process tables/Draw-in points: ";

      // A coordinate of a draw-in point: a number, or the words length or
      // width, the blank's (Geometry).
      double
      coordinate(const std::string          &text,
                 const std::string          &entry,
                 const blank::BlankGeometry *geometry)
      {
        const std::string word = Utilities::trim(text);
        if (word == "length" || word == "width")
          return geometry == nullptr
                   ? 0.
                   : (word == "length" ? geometry->length : geometry->width);
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
      }


      class DrawIn : public Interface
      {
      public:
        static void
        declare_parameters(ParameterHandler &prm)
        {
          prm.enter_subsection("Process tables");
          prm.declare_entry(
            "Draw-in points",
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
        parse_parameters(ParameterHandler &prm) override;

        void
        initialize(const SimulationAccess &simulation) override;

        void
        start(const SimulationAccess &simulation, const bool resume) override
        {
          if (!simulation.contact().active())
            return;
          std::vector<std::string> columns = {tables::punch_travel};
          for (const DrawInPoint &point : points)
            columns.push_back(point.name + tables::draw_in_suffix);
          file.open(simulation.output_directory() + "/" + tables::draw_in_table,
                    columns,
                    resume);
        }

        void
        execute(const SimulationAccess &simulation) override
        {
          if (!simulation.contact().active())
            return;
          const auto &vertices
            = simulation.sheet().triangulation().get_vertices();
          std::vector<double> row = {simulation.state().load};
          for (const DrawInPoint &point : points)
          {
            const Point<3> mid
              = blank::SheetThickness::mid_surface(point.location, vertices);
            row.push_back(point.initial_radius - std::hypot(mid[0], mid[1]));
          }
          file.add_row(row);
        }

      private:
        struct DrawInPoint
        {
          std::string name;
          // The entry and its coordinates' text ('NAME: X, Y').
          std::string entry, x, y;
          // Set instead: the direction of a ray from the origin ("x axis",
          // "y axis", "diagonal"), the point where it leaves the sheet.
          std::optional<Tensor<1, 2>> ray;
          // Where it lies on the sheet, and the initial distance of its
          // mid-surface point from the cup axis x = y = 0.
          blank::SheetThickness::Location location;
          double                          initial_radius = 0.;
        };

        std::vector<DrawInPoint> points;
        io::CsvFile              file;
      };


      void
      DrawIn::parse_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Process tables");
        const std::string list = prm.get("Draw-in points");
        prm.leave_subsection();
        points.clear();
        std::istringstream stream(list);
        std::string        entry;
        while (std::getline(stream, entry, ';'))
        {
          entry = Utilities::trim(entry);
          if (entry.empty())
            continue;
          const auto colon = entry.find(':');
          const auto comma
            = entry.find(',', colon == std::string::npos ? 0 : colon);
          DrawInPoint point;
          point.entry = entry;
          point.name
            = Utilities::trim(entry.substr(0, std::min(colon, entry.size())));
          // The name heads CSV columns (NAME_draw_in): a comma or quote in
          // it would split or open a column (D179).
          if (point.name.find_first_of(",\"") != std::string::npos)
            throw InputError(where + "the name '" + io::one_line(point.name)
                             + "' has a comma or a quote, which would break "
                               "the columns of "
                             + tables::draw_in_table
                             + "; allowed are names without them");
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
                               + "' is not of the form 'NAME: X, Y' or "
                                 "'NAME: x axis' ('y axis', 'diagonal')");
            point.x = entry.substr(colon + 1, comma - colon - 1);
            point.y = entry.substr(comma + 1);
            coordinate(point.x, entry, nullptr);
            coordinate(point.y, entry, nullptr);
          }
          points.push_back(point);
        }
      }


      void
      DrawIn::initialize(const SimulationAccess &simulation)
      {
        if (!simulation.contact().active())
          return;
        const blank::SheetThickness &sheet
          = simulation.thickness().sheet_thickness();
        for (DrawInPoint &point : points)
        {
          Point<2> requested;
          if (point.ray)
          {
            // Where the ray leaves the sheet: the last crossing of a face
            // edge.
            const std::vector<double> s = sheet.ray_crossings(*point.ray);
            if (s.empty())
              throw InputError(where + "the ray of " + point.name
                               + " does not meet the blank");
            requested = Point<2>(s.back() * *point.ray);
          }
          else
            requested
              = Point<2>(coordinate(point.x, point.entry, &simulation.blank()),
                         coordinate(point.y, point.entry, &simulation.blank()));
          const auto location = sheet.locate(requested);
          if (!location)
            throw InputError(
              where + point.name + " (" + std::to_string(requested[0]) + ", "
              + std::to_string(requested[1]) + ") is not on the blank");
          point.location = *location;
          const Point<3> mid
            = sheet.mid_surface(*location,
                                simulation.sheet().initial_vertices());
          point.initial_radius = std::hypot(mid[0], mid[1]);
        }
      }
    } // namespace

    DEEPDRAW_REGISTER_POSTPROCESSOR(
      DrawIn,
      "draw-in",
      "draw_in.csv (with tools), per converged load: the draw-in of the "
      "points of Process tables/Draw-in points.")
  } // namespace postprocess
} // namespace deepdraw
