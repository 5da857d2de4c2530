// Post-processor "earing": earing_<travel>mm.csv (runs with tools) at the
// travels of Output/Thickness profile travels, the cup height along the
// rim against the angle from the rolling direction (EaringProfile), and
// earing.gp to plot them (doc/user_guide.md §3.1).
#include <cmath>
#include <deepdraw/postprocess/earing_profile.h>
#include <deepdraw/postprocess/interface.h>
#include <deepdraw/postprocess/profile_travels.h>
#include <deepdraw/postprocess/punch_and_holder.h>
#include <deepdraw/postprocess/table_names.h>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      class Earing : public Interface
      {
      public:
        // Output/Thickness profile travels is declared by "thickness
        // profiles", Process tables/Punch tool by "punch force".
        void
        parse_parameters(ParameterHandler &prm) override
        {
          travels = parse_profile_travels(prm);
          punch.parse_parameters(prm);
        }

        void
        initialize(const SimulationAccess &simulation) override
        {
          if (!simulation.contact().active())
            return;
          punch.set_up(simulation.contact(), simulation.final_load());
          // The rim: the outline, not the symmetry planes.
          std::vector<types::boundary_id> rim_ids = {1, 3};
          if (!simulation.blank().symmetry_plane_x)
            rim_ids.push_back(0);
          if (!simulation.blank().symmetry_plane_y)
            rim_ids.push_back(2);
          profile.set_up(
            simulation.sheet().triangulation(),
            simulation.sheet().initial_vertices(),
            rim_ids,
            simulation.material().get_parameters().rolling_direction_angle);
        }

        std::vector<double>
        requested_loads(const SimulationAccess &simulation) const override
        {
          if (!simulation.contact().active())
            return {};
          return travels_within(travels, simulation.final_load());
        }

        void
        start(const SimulationAccess &simulation, bool) override
        {
          const std::vector<double> within = requested_loads(simulation);
          if (within.empty())
            return;
          std::vector<std::string> labels;
          for (const double travel : within)
            labels.push_back(travel_label(travel));
          EaringProfile::write_plot_script(simulation.output_directory(),
                                           labels);
        }

        void
        execute(const SimulationAccess &simulation) override
        {
          const double load = simulation.state().load;
          for (const double travel : requested_loads(simulation))
            if (std::abs(travel - load) < 1e-9 * std::max(1., travel))
              profile.write(simulation.output_directory(),
                            travel_label(travel),
                            simulation.sheet().triangulation().get_vertices(),
                            punch.punch_direction());
        }

      private:
        std::vector<double> travels;
        PunchAndHolder      punch;
        EaringProfile       profile;
      };
    } // namespace

    DEEPDRAW_REGISTER_POSTPROCESSOR(
      Earing,
      "earing",
      "earing_<travel>mm.csv (with tools) at Output/Thickness profile "
      "travels: the cup height along the rim against the angle from the "
      "rolling direction, and earing.gp to plot them.")
  } // namespace postprocess
} // namespace deepdraw
