// Post-processor "section profile" (doc/user_guide.md §3, D153): the
// mid-surface of the sheet along a line of reference points given in
// initial coordinates, at the end of every stage (so before and after a
// release), as section_profile_stage<N>.csv and section_profile.png
// (gnuplot), with the NUMISHEET'93 measures of a channel section
// (channel_measures.h) in section_measures.csv.
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deepdraw/io/csv_file.h>
#include <deepdraw/io/gnuplot.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/postprocess/channel_measures.h>
#include <deepdraw/postprocess/interface.h>
#include <fstream>
#include <iostream>
#include <sstream>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      const std::string subsection = "Postprocess/Section profile/";

      // "a, b" as two numbers; where: the message's start.
      std::array<double, 2>
      number_pair(const std::string &text, const std::string &where)
      {
        const std::vector<std::string> parts
          = Utilities::split_string_list(text, ',');
        std::array<double, 2> values{};
        bool                  ok = parts.size() == 2;
        for (unsigned int k = 0; ok && k < 2; ++k)
          try
          {
            values[k] = Utilities::string_to_double(parts[k]);
            ok        = std::isfinite(values[k]);
          }
          catch (...)
          {
            ok = false;
          }
        if (!ok)
          throw InputError(where + "'" + io::one_line(text)
                           + "' is not two numbers 'a, b'");
        return values;
      }


      class SectionProfile : public Interface
      {
      public:
        static void
        declare_parameters(ParameterHandler &prm);
        void
        parse_parameters(ParameterHandler &prm) override;
        void
        initialize(const SimulationAccess &simulation) override;
        void
        start(const SimulationAccess &simulation, bool resume) override;
        void
        execute(const SimulationAccess &) override
        {
        }
        void
        end_stage(const SimulationAccess &simulation) override;

      private:
        // The section's points (s, z): s along the line from its start in
        // the plane, z the height.
        std::vector<Point<2>>
        section_points(const std::vector<Point<3>> &mid_surface) const;
        void
        write_plot(const SimulationAccess &simulation) const;

        Point<2>     start_point, end_point;
        unsigned int n_points = 101;
        // The ranges of the initial distance s0 of the bottom, the wall and
        // the flange; empty: no measures.
        std::vector<std::array<double, 2>>           parts;
        std::vector<double>                          distances;
        std::vector<blank::SheetThickness::Location> locations;
        io::CsvFile                                  measures;
      };


      void
      SectionProfile::declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Postprocess");
        prm.enter_subsection("Section profile");
        prm.declare_entry("Line",
                          "0, 0; 1, 0",
                          Patterns::Anything(),
                          "The section: from the point 'X1, Y1' to 'X2, Y2' "
                          "of the blank (initial coordinates, mm), separated "
                          "by ';'. The mid-surface is sampled there at the "
                          "end of every stage.");
        prm.declare_entry("Number of points",
                          "101",
                          Patterns::Integer(2, 100000),
                          "Points of the section, equally spaced along the "
                          "line.");
        prm.declare_entry("Channel parts",
                          "",
                          Patterns::Anything(),
                          "The parts of a channel section for the "
                          "NUMISHEET'93 measures theta1, theta2, rho "
                          "(section_measures.csv): 'bottom: a, b; wall: c, d; "
                          "flange: e, f', ranges of the initial distance "
                          "along the line (mm); empty: no measures.");
        prm.leave_subsection();
        prm.leave_subsection();
      }


      void
      SectionProfile::parse_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Postprocess");
        prm.enter_subsection("Section profile");
        const std::vector<std::string> ends
          = Utilities::split_string_list(prm.get("Line"), ';');
        if (ends.size() != 2)
          throw InputError(subsection + "Line = '"
                           + io::one_line(prm.get("Line"))
                           + "': expected 'X1, Y1; X2, Y2'");
        const auto a = number_pair(ends[0], subsection + "Line: ");
        const auto b = number_pair(ends[1], subsection + "Line: ");
        start_point  = Point<2>(a[0], a[1]);
        end_point    = Point<2>(b[0], b[1]);
        if (!(start_point.distance(end_point) > 0.))
          throw InputError(subsection + "Line: its two points are the same");
        n_points = prm.get_integer("Number of points");
        parts.clear();
        const std::string              names[3] = {"bottom", "wall", "flange"};
        const std::vector<std::string> items
          = Utilities::split_string_list(prm.get("Channel parts"), ';');
        for (unsigned int k = 0; k < items.size(); ++k)
        {
          const auto colon = items[k].find(':');
          if (items.size() != 3 || colon == std::string::npos
              || Utilities::trim(items[k].substr(0, colon)) != names[k])
            throw InputError(subsection + "Channel parts = '"
                             + io::one_line(prm.get("Channel parts"))
                             + "': expected 'bottom: a, b; wall: c, d; "
                               "flange: e, f'");
          parts.push_back(number_pair(items[k].substr(colon + 1),
                                      subsection + "Channel parts: "));
        }
        prm.leave_subsection();
        prm.leave_subsection();
      }


      void
      SectionProfile::initialize(const SimulationAccess &simulation)
      {
        const blank::SheetThickness &sheet
          = simulation.thickness().sheet_thickness();
        distances.clear();
        locations.clear();
        const double length = start_point.distance(end_point);
        for (unsigned int k = 0; k < n_points; ++k)
        {
          const double s0       = length * k / (n_points - 1);
          const auto   location = sheet.locate(
            start_point + (s0 / length) * (end_point - start_point));
          if (!location)
          {
            std::ostringstream text;
            text << subsection << "Line: the point at " << s0
                 << " mm from its start is not on the blank";
            throw InputError(text.str());
          }
          distances.push_back(s0);
          locations.push_back(*location);
        }
      }


      void
      SectionProfile::start(const SimulationAccess &simulation,
                            const bool              resume)
      {
        if (!parts.empty())
          measures.open(simulation.output_directory() + "/section_measures.csv",
                        {"stage", "load", "theta1_deg", "theta2_deg", "rho_mm"},
                        resume);
      }


      std::vector<Point<2>>
      SectionProfile::section_points(
        const std::vector<Point<3>> &mid_surface) const
      {
        // The plane of the section: its line's direction in x, y, and z.
        const Tensor<1, 2> d
          = (end_point - start_point) / start_point.distance(end_point);
        std::vector<Point<2>> points;
        for (const Point<3> &x : mid_surface)
          points.emplace_back((x[0] - start_point[0]) * d[0]
                                + (x[1] - start_point[1]) * d[1],
                              x[2]);
        return points;
      }


      void
      SectionProfile::end_stage(const SimulationAccess &simulation)
      {
        const auto &vertices
          = simulation.sheet().triangulation().get_vertices();
        std::vector<Point<3>> mid_surface;
        for (const auto &location : locations)
          mid_surface.push_back(
            blank::SheetThickness::mid_surface(location, vertices));
        const std::vector<Point<2>>      section = section_points(mid_surface);
        std::vector<std::vector<double>> rows;
        for (unsigned int k = 0; k < mid_surface.size(); ++k)
          rows.push_back({distances[k],
                          mid_surface[k][0],
                          mid_surface[k][1],
                          mid_surface[k][2],
                          section[k][0]});
        const unsigned int stage = simulation.stage_index() + 1;
        io::write_csv_file_atomically(simulation.output_directory()
                                        + "/section_profile_stage"
                                        + std::to_string(stage) + ".csv",
                                      {"s0", "x", "y", "z", "s"},
                                      rows);
        if (!parts.empty())
        {
          std::array<std::vector<Point<2>>, 3> part_points;
          for (unsigned int k = 0; k < section.size(); ++k)
            for (unsigned int p = 0; p < 3; ++p)
              if (distances[k] >= parts[p][0] && distances[k] <= parts[p][1])
                part_points[p].push_back(section[k]);
          try
          {
            const ChannelMeasures m = channel_measures(part_points[0],
                                                       part_points[1],
                                                       part_points[2]);
            measures.add_row({double(stage),
                              simulation.state().load,
                              m.theta1,
                              m.theta2,
                              std::min(m.rho, 1e12)});
          }
          catch (const std::invalid_argument &error)
          {
            throw InputError(subsection + "Channel parts: " + error.what()
                             + "; widen the ranges or raise Number of points");
          }
        }
        write_plot(simulation);
      }


      void
      SectionProfile::write_plot(const SimulationAccess &simulation) const
      {
        std::ostringstream gp;
        gp << "# Written by deepdraw's section profile (doc/user_guide.md "
              "§3); run 'gnuplot section_profile.gp' here.\n"
              "set terminal png size 900,400 font 'DejaVuSans,8' noenhanced\n"
              "set output 'section_profile.png'\n"
              "set datafile separator ','\nset datafile columnheaders\n"
              "set size ratio -1\nset grid\nset key outside right\n"
              "set xlabel 's along the section (mm)'\nset ylabel 'z (mm)'\n"
              "plot ";
        for (unsigned int s = 0; s <= simulation.stage_index(); ++s)
          gp << (s ? ", \\\n     " : "") << "'section_profile_stage" << s + 1
             << ".csv' using 5:4 with lines title 'end of stage " << s + 1
             << " (" << simulation.stages()[s].name << ")'";
        gp << "\n";
        const std::string message
          = io::plot_with_gnuplot(simulation.output_directory(),
                                  "section_profile",
                                  gp.str());
        if (message.find("written") == std::string::npos)
          std::cerr << "deepdraw: " << message << std::endl;
      }
    } // namespace

    DEEPDRAW_REGISTER_POSTPROCESSOR(
      SectionProfile,
      "section profile",
      "section_profile_stage<N>.csv and section_profile.png: the mid-surface "
      "along Postprocess/Section profile/Line at the end of every stage "
      "(before and after a release); section_measures.csv: the NUMISHEET'93 "
      "angles theta1, theta2 and wall radius rho of a channel section.")
  } // namespace postprocess
} // namespace deepdraw
