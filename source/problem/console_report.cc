#include <deepdraw/parallel/ranks.h>
#include <deepdraw/problem/console_report.h>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace deepdraw
{
  namespace problem
  {
    namespace
    {
      std::string
      format_seconds(const double seconds)
      {
        std::ostringstream text;
        text << std::fixed << std::setprecision(seconds < 100. ? 1 : 0)
             << seconds << " s";
        return text.str();
      }
    } // namespace


    std::string
    format_load(const double load)
    {
      std::ostringstream text;
      text << std::setprecision(6) << load;
      return text.str();
    }


    ConsoleReport::ConsoleReport(const bool quiet)
        : quiet(quiet)
    {
    }


    void
    ConsoleReport::model(const postprocess::SimulationAccess &simulation,
                         const unsigned int                   n_unknowns,
                         const std::string                   &element,
                         const bool                           resumed)
    {
      first_load = simulation.state().load;
      if (quiet)
        return;
      const unsigned int n_u = simulation.sheet().n_displacement_dofs();
      std::cout << "deepdraw: "
                << simulation.sheet().triangulation().n_active_cells()
                << " cells, " << n_u << " displacement unknowns, "
                << n_unknowns - n_u << " contact unknowns, " << element
                << " element"
                << (parallel::n_ranks() > 1
                      ? ", " + std::to_string(parallel::n_ranks())
                          + " MPI ranks"
                      : std::string())
                << (resumed ? ", resumed at load " + format_load(first_load)
                            : std::string())
                << std::endl;
    }


    void
    ConsoleReport::stage(const postprocess::SimulationAccess &simulation)
    {
      if (quiet)
        return;
      const process::Stage &stage
        = simulation.stages()[simulation.stage_index()];
      std::cout << "deepdraw: stage " << simulation.stage_index() + 1 << " '"
                << stage.name << "' (" << process::to_string(stage.kind)
                << ") from load " << format_load(stage.start_load) << " to "
                << format_load(stage.end_load) << std::endl;
      // The node each release support found (D151).
      const std::vector<unsigned int> &nodes
        = simulation.state().release_support_vertices;
      const std::vector<dealii::Point<3>> &x
        = simulation.sheet().triangulation().get_vertices();
      for (unsigned int s = 0; s < nodes.size() && s < stage.supports.size();
           ++s)
        std::cout << "  support '" << stage.supports[s].item << "': node "
                  << nodes[s] << " at (" << x[nodes[s]][0] << ", "
                  << x[nodes[s]][1] << ", " << x[nodes[s]][2] << "), held "
                  << process::component_names(stage.supports[s].components)
                  << std::endl;
    }


    void
    ConsoleReport::cut_back(const double load, const std::string &reason) const
    {
      if (!quiet)
        std::cout << "  load " << format_load(load) << ": " << reason
                  << ", cutting the increment back" << std::endl;
    }


    void
    ConsoleReport::increment(const postprocess::SimulationAccess &simulation,
                             const unsigned int                   iterations,
                             const unsigned int cut_backs) const
    {
      if (quiet)
        return;
      const state::SimulationState       &state = simulation.state();
      const postprocess::IncrementReport &report
        = simulation.increment_report();
      // Remaining time: the load still to go at the mean rate of this run
      // so far.
      const double elapsed = timer.wall_time();
      const double done    = state.load - first_load;
      const double remaining
        = done > 0. ? elapsed / done * (simulation.final_load() - state.load)
                    : 0.;
      std::ostringstream line;
      line << "increment " << std::setw(4) << state.increment_number
           << "  load " << std::setw(9) << format_load(state.load)
           << "  iterations " << std::setw(2) << iterations << "  cut-backs "
           << cut_backs << std::scientific << std::setprecision(2)
           << "  residuals " << report.force_residual << " "
           << report.contact_residual << std::defaultfloat
           << "  plastic points " << report.plastic_points;
      if (simulation.contact().active())
        line << "  stick/slip " << simulation.contact().n_stick() << "/"
             << simulation.contact().n_slip();
      line << std::fixed << std::setprecision(3) << "  time "
           << simulation.increment_wall_time() << " s  elapsed "
           << format_seconds(elapsed) << "  remaining ~"
           << format_seconds(remaining);
      std::cout << line.str() << std::endl;
    }


    void
    ConsoleReport::refined(const unsigned int cells,
                           const unsigned int iterations) const
    {
      if (!quiet)
        std::cout << "  refined to " << cells << " cells, re-equilibrated in "
                  << iterations << " iteration(s)" << std::endl;
    }


    void
    ConsoleReport::finished(const postprocess::SimulationAccess &simulation,
                            const double                         seconds,
                            const std::vector<std::string> &summaries) const
    {
      std::cout << "deepdraw: finished at load "
                << format_load(simulation.state().load) << " after "
                << simulation.state().increment_number << " increments in "
                << format_seconds(seconds) << "; results in "
                << simulation.output_directory() << std::endl;
      for (const std::string &line : summaries)
        std::cout << "deepdraw: " << line << std::endl;
    }
  } // namespace problem
} // namespace deepdraw
