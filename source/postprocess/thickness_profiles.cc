// Post-processor "thickness profiles": thickness_OX/OY/OD_<travel>mm.csv
// (runs with tools) at the travels of Output/Thickness profile travels: the
// thickness strain ln(t/t0) along the rays from the origin along x, y and
// the diagonal x = y, sampled where they cross a face edge, against the
// initial distance s0 (doc/user_guide.md §3.1). The load stepping lands on
// the travels: the profiles are computed there, not interpolated (D6).
#include <cmath>
#include <deepdraw/io/csv_file.h>
#include <deepdraw/postprocess/interface.h>
#include <deepdraw/postprocess/profile_travels.h>
#include <deepdraw/postprocess/table_names.h>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      class ThicknessProfiles : public Interface
      {
      public:
        static void
        declare_parameters(ParameterHandler &prm)
        {
          declare_profile_travels(prm);
        }

        void
        parse_parameters(ParameterHandler &prm) override
        {
          travels = parse_profile_travels(prm);
        }

        void
        initialize(const SimulationAccess &simulation) override;

        std::vector<double>
        requested_loads(const SimulationAccess &simulation) const override
        {
          // Square-cup tables: runs with tools only.
          if (!simulation.contact().active())
            return {};
          return travels_within(travels, simulation.final_load());
        }

        void
        execute(const SimulationAccess &simulation) override;

      private:
        // A ray: its name and the initial distance s0 from the origin and
        // the location on the sheet of each point.
        struct Profile
        {
          std::string name;
          std::vector<std::pair<double, blank::SheetThickness::Location>>
            points;
        };

        std::vector<double>  travels;
        std::vector<Profile> profiles;
      };


      void
      ThicknessProfiles::initialize(const SimulationAccess &simulation)
      {
        profiles.clear();
        if (!simulation.contact().active())
          return;
        const blank::SheetThickness &sheet
          = simulation.thickness().sheet_thickness();
        const std::pair<const char *, Tensor<1, 2>> rays[]
          = {{"OX", Tensor<1, 2>({1., 0.})},
             {"OY", Tensor<1, 2>({0., 1.})},
             {"OD", Tensor<1, 2>({std::sqrt(0.5), std::sqrt(0.5)})}};
        for (const auto &[name, direction] : rays)
        {
          Profile profile{name, {}};
          for (const double s : sheet.ray_crossings(direction))
            if (const auto location = sheet.locate(Point<2>(s * direction)))
              profile.points.emplace_back(s, *location);
          profiles.push_back(profile);
        }
      }


      void
      ThicknessProfiles::execute(const SimulationAccess &simulation)
      {
        const double load = simulation.state().load;
        for (const double travel : requested_loads(simulation))
        {
          if (!(std::abs(travel - load) < 1e-9 * std::max(1., travel)))
            continue;
          const auto &vertices
            = simulation.sheet().triangulation().get_vertices();
          const blank::SheetThickness &sheet
            = simulation.thickness().sheet_thickness();
          for (const Profile &profile : profiles)
          {
            std::vector<std::vector<double>> rows;
            for (const auto &[s0, location] : profile.points)
              rows.push_back({s0,
                              std::log(sheet.thickness(location, vertices)
                                       / simulation.blank().thickness)});
            io::write_csv_file_atomically(
              simulation.output_directory() + "/"
                + thickness_profile_file(profile.name, travel),
              {tables::profile_distance, tables::thickness_strain},
              rows);
          }
        }
      }
    } // namespace

    DEEPDRAW_REGISTER_POSTPROCESSOR(
      ThicknessProfiles,
      "thickness profiles",
      "thickness_OX/OY/OD_<travel>mm.csv (with tools) at Output/Thickness "
      "profile travels: the thickness strain along the x axis, the y axis "
      "and the diagonal.")
  } // namespace postprocess
} // namespace deepdraw
