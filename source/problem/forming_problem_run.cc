// The increment loop of FormingProblem (doc/architecture.md, "Data flow of
// a run"): load stepping with cut-backs, the checks that no tool passed
// through the sheet, output after each converged increment, checkpoints and
// the clean stop on a signal (doc/user_guide.md §6).
#include <algorithm>
#include <cmath>
#include <deal.II/base/timer.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/problem/forming_problem.h>
#include <deepdraw/state/stop_request.h>
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
      format_load(const double load)
      {
        std::ostringstream text;
        text << std::setprecision(6) << load;
        return text.str();
      }

      std::string
      format_seconds(const double seconds)
      {
        std::ostringstream text;
        text << std::fixed << std::setprecision(seconds < 100. ? 1 : 0)
             << seconds << " s";
        return text.str();
      }

      bool
      is_landing(const std::vector<double> &loads, const double load)
      {
        return std::any_of(loads.begin(),
                           loads.end(),
                           [&](const double l) {
                             return std::abs(l - load)
                                    < 1e-9 * std::max(1., std::abs(l));
                           });
      }
    } // namespace


    std::vector<double>
    FormingProblem::landing_loads() const
    {
      std::vector<double> loads;
      if (output_parameters.output_interval > 0.)
        for (double load = output_parameters.output_interval;
             load < increment_parameters.final_load;
             load += output_parameters.output_interval)
          loads.push_back(load);
      // The thickness profiles are computed at their travels, not
      // interpolated (D6).
      loads.insert(loads.end(), profile_travels.begin(), profile_travels.end());
      return loads;
    }


    void
    FormingProblem::start_run(const RunOptions &options)
    {
      if (options.resume)
        restore_checkpoint();
      else if (contact.active())
      {
        contact.start_increment(0., 0.);
        // Tool placement, contact fields and states of the initial state;
        // a tool inside the blank or turned away from it is an input error
        // (D56), found before anything is written.
        assemble(newton_unknowns, homogeneous_constraints, false);
        contact.check_initial_placement(triangulation.get_vertices(),
                                        geometry.thickness);
        const unsigned int penetrating
          = contact.n_initial_penetrations(triangulation.get_vertices());
        if (penetrating > 0 && !options.quiet)
          std::cout << "deepdraw: " << penetrating
                    << " sheet nodes start inside a tool; the first "
                       "increment pushes them out"
                    << std::endl;
        contact.commit(newton_unknowns);
        state.contact = contact.committed_history();
      }
      try
      {
        open_output_files(options.resume);
      }
      catch (const InputError &)
      {
        throw;
      }
      catch (const std::exception &error)
      {
        throw InputError("Output/Output directory: cannot write results to '"
                         + output_parameters.output_directory
                         + "': " + error.what());
      }
      if (!options.resume)
        write_vtu(0.);
      committed_table_sizes
        = state::csv_table_sizes(output_parameters.output_directory);
    }


    void
    FormingProblem::run(const RunOptions &options)
    {
      Timer run_timer;
      start_run(options);
      if (!options.quiet)
        std::cout << "deepdraw: " << triangulation.n_active_cells()
                  << " cells, " << dof_handler.n_dofs()
                  << " displacement unknowns, "
                  << newton_unknowns.size() - dof_handler.n_dofs()
                  << " contact unknowns, "
                  << fe::to_string(element_parameters.technology) << " element"
                  << (options.resume
                        ? ", resumed at load " + format_load(state.load)
                        : std::string())
                  << std::endl;

      const std::vector<double> landings = landing_loads();
      solver::IncrementControl  control(increment_parameters, landings);
      if (options.resume)
        control.restore({state.load, state.next_increment});
      const double first_load = control.current_load();

      // The times of an increment include its failed attempts (cut-backs):
      // they are reset only once it has converged.
      assembly_time             = 0.;
      solve_time                = 0.;
      double search_time_before = contact.search_time();
      Timer  increment_timer;
      while (!control.finished())
      {
        if (const int signal_number = state::requested_stop_signal())
          stop_cleanly("stopped by " + state::signal_name(signal_number));

        const double     old_load   = control.current_load();
        const double     new_load   = old_load + control.next_increment();
        unsigned int     iterations = 0;
        std::string      reason;
        IncrementOutcome outcome
          = solve_checked_increment(old_load, new_load, iterations, reason);
        if (outcome != IncrementOutcome::converged)
        {
          if (!options.quiet)
            std::cout << "  load " << format_load(new_load) << ": " << reason
                      << ", cutting the increment back" << std::endl;
          trial_history             = state.history;
          trial_enhanced_parameters = state.enhanced_parameters;
          if (!control.cut_back())
          {
            const bool too_small = control.next_increment()
                                   < increment_parameters.minimum_increment;
            stop_cleanly(
              "the increment from load " + format_load(old_load) + " to "
              + format_load(new_load) + " failed (" + reason + ") after "
              + std::to_string(control.cut_backs_of_current_increment())
              + " attempt(s), and "
              + (too_small ? "a further cut-back would go below Load "
                             "stepping/Minimum increment"
                           : "Load stepping/Maximum cut-backs is reached"));
          }
          continue;
        }

        const unsigned int cut_backs = control.cut_backs_of_current_increment();
        control.accept(iterations);
        commit_increment();
        ++state.increment_number;
        state.next_increment = control.state().increment;

        Timer output_timer;
        if (output_parameters.output_interval <= 0. || control.finished()
            || is_landing(landings, new_load))
          write_vtu(new_load);
        write_increment_tables(new_load);
        const IncrementRecord record{new_load - old_load,
                                     iterations,
                                     cut_backs,
                                     output_timer.wall_time(),
                                     contact.search_time() - search_time_before,
                                     increment_timer.wall_time()};
        write_statistics_row(record);
        if (!options.quiet)
        {
          // Remaining time: the load still to go at the mean rate of this
          // run so far.
          const double elapsed = run_timer.wall_time();
          const double done    = state.load - first_load;
          const double remaining
            = done > 0. ? elapsed / done
                            * (increment_parameters.final_load - state.load)
                        : 0.;
          print_increment_line(record, elapsed, remaining);
        }
        // Adaptive refinement and re-equilibration at this load (D80).
        const std::size_t refinements = refinement_history.size();
        if (!adapt_mesh(control.finished(), reason))
          stop_cleanly("the re-equilibration after refining the mesh at load "
                       + format_load(state.load) + " failed (" + reason + ")");
        if (!options.quiet && refinement_history.size() > refinements)
          std::cout << "  refined to " << triangulation.n_active_cells()
                    << " cells, re-equilibrated in "
                    << refinement_history.back().iterations << " iteration(s)"
                    << std::endl;
        committed_table_sizes
          = state::csv_table_sizes(output_parameters.output_directory);
        if (checkpoint_parameters.interval > 0
            && state.increment_number % checkpoint_parameters.interval == 0)
          save_checkpoint();
        assembly_time      = 0.;
        solve_time         = 0.;
        search_time_before = contact.search_time();
        increment_timer.restart();
      }
      std::cout << "deepdraw: finished at load "
                << format_load(control.current_load()) << " after "
                << state.increment_number << " increments in "
                << format_seconds(wall_timer.wall_time()) << "; results in "
                << output_parameters.output_directory << std::endl;
    }


    FormingProblem::IncrementOutcome
    FormingProblem::solve_checked_increment(const double  old_load,
                                            const double  new_load,
                                            unsigned int &iterations,
                                            std::string  &reason)
    {
      // A tool that moves farther than the search distance in one
      // increment can pass through the sheet unseen (D56).
      reason = contact.active() ? contact.check_tool_motion(old_load, new_load)
                                : std::string();
      if (!reason.empty())
        return IncrementOutcome::diverged;
      const IncrementOutcome outcome
        = solve_increment(old_load, new_load, iterations);
      reason = solver::describe(outcome);
      if (outcome != IncrementOutcome::converged || !contact.active())
        return outcome;
      reason = contact.check_tool_sides(triangulation.get_vertices(),
                                        newton_unknowns,
                                        geometry.thickness);
      if (reason.empty())
        reason = contact.check_tool_motion(old_load, new_load, newton_unknowns);
      return reason.empty() ? outcome : IncrementOutcome::diverged;
    }


    void
    FormingProblem::stop_cleanly(const std::string &reason)
    {
      std::string where = "; the results up to load " + format_load(state.load)
                          + " are in " + output_parameters.output_directory;
      try
      {
        save_checkpoint();
        where += ", with a checkpoint to continue from (--resume)";
      }
      catch (const std::exception &error)
      {
        where += " (no checkpoint: " + std::string(error.what()) + ")";
      }
      throw RunFailure(reason + where);
    }


    void
    FormingProblem::write_statistics_row(const IncrementRecord &record)
    {
      const double force_residual
        = residual_history.empty() ? 0. : residual_history.back();
      const double contact_residual = contact_residual_history.empty()
                                        ? 0.
                                        : contact_residual_history.back();
      const solver::LinearSolver::Statistics solver_statistics
        = linear_solver->statistics();
      statistics_file.add_row(
        {double(state.increment_number),
         state.load,
         record.load_increment,
         double(record.iterations),
         double(record.cut_backs),
         force_residual,
         contact_residual,
         double(n_plastic_points),
         double(contact_changes),
         double(contact.n_stick()),
         double(contact.n_slip()),
         assembly_time,
         record.search_time,
         solve_time,
         record.output_time,
         record.wall_time,
         sheet_volume(),
         double(solver_statistics.factorized_unknowns),
         double(solver_statistics.symbolic_analyses
                - reported_solver_statistics.symbolic_analyses)});
      reported_solver_statistics = solver_statistics;
    }


    void
    FormingProblem::print_increment_line(const IncrementRecord &record,
                                         const double           elapsed,
                                         const double           remaining) const
    {
      std::ostringstream line;
      line << "increment " << std::setw(4) << state.increment_number
           << "  load " << std::setw(9) << format_load(state.load)
           << "  iterations " << std::setw(2) << record.iterations
           << "  cut-backs " << record.cut_backs << std::scientific
           << std::setprecision(2) << "  residuals "
           << (residual_history.empty() ? 0. : residual_history.back()) << " "
           << (contact_residual_history.empty()
                 ? 0.
                 : contact_residual_history.back())
           << std::defaultfloat << "  plastic points " << n_plastic_points;
      if (contact.active())
        line << "  stick/slip " << contact.n_stick() << "/" << contact.n_slip();
      line << std::fixed << std::setprecision(3) << "  time "
           << record.wall_time << " s  elapsed " << format_seconds(elapsed)
           << "  remaining ~" << format_seconds(remaining);
      std::cout << line.str() << std::endl;
    }
  } // namespace problem
} // namespace deepdraw
