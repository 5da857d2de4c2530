// The run of FormingProblem (doc/architecture.md, "Data flow of a run"):
// the stages one after the other, and in each the load stepping with
// cut-backs, the checks that no tool passed through the sheet, the
// post-processors after each converged increment, checkpoints and the
// clean stop on a signal (doc/user_guide.md §6).
#include <algorithm>
#include <cmath>
#include <deepdraw/io/input_error.h>
#include <deepdraw/problem/forming_problem.h>
#include <deepdraw/state/checkpoint.h>
#include <deepdraw/state/stop_request.h>
#include <filesystem>
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


    void
    FormingProblem::start_run(const RunOptions &options)
    {
      if (options.resume)
        restore_checkpoint();
      else if (contact_coupling.active())
      {
        contact_coupling.start_increment(0., 0.);
        // Tool placement, contact fields and states of the initial state;
        // a tool inside the blank or turned away from it is an input error
        // (D56), found before anything is written.
        assemble(newton_unknowns, constraints.homogeneous(), false);
        contact_coupling.check_initial_placement(
          discretisation.triangulation().get_vertices(),
          parameters.geometry.thickness);
        const unsigned int penetrating
          = contact_coupling.n_initial_penetrations(
            discretisation.triangulation().get_vertices());
        if (penetrating > 0 && !options.quiet)
          std::cout << "deepdraw: " << penetrating
                    << " sheet nodes start inside a tool; the first "
                       "increment pushes them out"
                    << std::endl;
        contact_coupling.commit(newton_unknowns);
        committed.contact = contact_coupling.committed_history();
      }
      // A failure to open the outputs is an input error (exit code 2, D11),
      // after which nothing may be left behind: a directory made here is
      // removed again.
      const std::string &directory = parameters.output.output_directory;
      const bool         existed   = std::filesystem::exists(directory);
      try
      {
        std::filesystem::create_directories(directory);
        postprocessors.start(*this, options.resume);
        newton_log.open(directory, options.resume);
        adaptation->open(directory, options.resume);
      }
      catch (const std::exception &error)
      {
        if (!existed)
        {
          std::error_code ignored;
          std::filesystem::remove_all(directory, ignored);
        }
        if (dynamic_cast<const InputError *>(&error) != nullptr)
          throw;
        throw InputError("Output/Output directory: cannot write results to '"
                         + directory + "': " + error.what());
      }
      if (!options.resume)
        postprocessors.execute(*this);
      table_sizes = state::csv_table_sizes(directory);
    }


    void
    FormingProblem::run(const RunOptions &options)
    {
      RunProgress run;
      run.quiet = options.quiet;
      start_run(options);
      run.first_load = committed.load;
      if (!options.quiet)
        std::cout << "deepdraw: "
                  << discretisation.triangulation().n_active_cells()
                  << " cells, " << discretisation.n_displacement_dofs()
                  << " displacement unknowns, "
                  << newton_unknowns.size()
                       - discretisation.n_displacement_dofs()
                  << " contact unknowns, "
                  << fe::to_string(parameters.element.technology) << " element"
                  << (options.resume
                        ? ", resumed at load " + format_load(committed.load)
                        : std::string())
                  << std::endl;
      while (true)
      {
        if (!committed.stage_completed)
        {
          run_stage(run);
          end_stage();
        }
        if (committed.stage + 1 >= parameters.stages.size())
          break;
        begin_stage(committed.stage + 1);
        if (!options.quiet)
          std::cout << "deepdraw: stage " << committed.stage + 1 << " '"
                    << stage().name << "' (" << process::to_string(stage().kind)
                    << ") from load " << format_load(stage().start_load)
                    << " to " << format_load(stage().end_load) << std::endl;
      }
      std::cout << "deepdraw: finished at load " << format_load(committed.load)
                << " after " << committed.increment_number << " increments in "
                << format_seconds(wall_timer.wall_time()) << "; results in "
                << parameters.output.output_directory << std::endl;
    }


    void
    FormingProblem::run_stage(const RunProgress &run)
    {
      std::vector<double> landings;
      for (const double load : postprocessors.requested_loads(*this))
        if (load > stage().start_load && load < stage().end_load)
          landings.push_back(load);
      solver::IncrementControl control(stage().load_stepping, landings);
      control.restore({committed.load, committed.next_increment});
      // The times of an increment include its failed attempts (cut-backs):
      // they are reset only once it has converged.
      progress.assembly_time = progress.solve_time = 0.;
      double search_time_before = contact_coupling.search_time();
      increment_timer.restart();
      while (!control.finished())
      {
        if (const int signal_number = state::requested_stop_signal())
          stop_cleanly("stopped by " + state::signal_name(signal_number));

        const double old_load   = control.current_load();
        const double new_load   = old_load + control.next_increment();
        unsigned int iterations = 0;
        std::string  reason;
        if (solve_checked_increment(old_load, new_load, iterations, reason)
            != IncrementOutcome::converged)
        {
          if (!run.quiet)
            std::cout << "  load " << format_load(new_load) << ": " << reason
                      << ", cutting the increment back" << std::endl;
          trial_history             = committed.history;
          trial_enhanced_parameters = committed.enhanced_parameters;
          if (!control.cut_back())
          {
            const bool too_small = control.next_increment()
                                   < stage().load_stepping.minimum_increment;
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
        ++committed.increment_number;
        committed.next_increment = control.state().increment;
        report.search_time
          = contact_coupling.search_time() - search_time_before;
        at_stage_end = control.finished();
        at_landing   = at_stage_end || is_landing(landings, new_load);
        report_increment(new_load - old_load, iterations, cut_backs, run);

        // Adaptive refinement and re-equilibration at this load (D80).
        const bool last = control.finished()
                          && committed.stage + 1 == parameters.stages.size();
        const std::size_t refinements = adaptation->records().size();
        if (!adapt_mesh(last, reason))
          stop_cleanly("the re-equilibration after refining the mesh at load "
                       + format_load(committed.load) + " failed (" + reason
                       + ")");
        if (!run.quiet && adaptation->records().size() > refinements)
          std::cout << "  refined to "
                    << discretisation.triangulation().n_active_cells()
                    << " cells, re-equilibrated in "
                    << adaptation->records().back().iterations
                    << " iteration(s)" << std::endl;
        table_sizes
          = state::csv_table_sizes(parameters.output.output_directory);
        if (parameters.checkpoint.interval > 0
            && committed.increment_number % parameters.checkpoint.interval == 0)
          save_checkpoint();
        progress.assembly_time = progress.solve_time = 0.;
        search_time_before = contact_coupling.search_time();
        increment_timer.restart();
      }
    }


    void
    FormingProblem::end_stage()
    {
      postprocessors.end_stage(*this);
      committed.stage_completed = true;
      table_sizes = state::csv_table_sizes(parameters.output.output_directory);
      // A later run can begin the next stage from here (D101).
      if (committed.stage + 1 < parameters.stages.size())
        save_checkpoint();
    }


    FormingProblem::IncrementOutcome
    FormingProblem::solve_checked_increment(const double  old_load,
                                            const double  new_load,
                                            unsigned int &iterations,
                                            std::string  &reason)
    {
      // A tool that moves farther than the search distance in one
      // increment can pass through the sheet unseen (D56).
      reason = contact_coupling.active()
                 ? contact_coupling.check_tool_motion(old_load, new_load)
                 : std::string();
      if (!reason.empty())
        return IncrementOutcome::diverged;
      const IncrementOutcome outcome
        = solve_increment(old_load, new_load, iterations);
      reason = solver::describe(outcome);
      if (outcome != IncrementOutcome::converged || !contact_coupling.active())
        return outcome;
      reason = contact_coupling.check_tool_sides(
        discretisation.triangulation().get_vertices(),
        newton_unknowns,
        parameters.geometry.thickness);
      if (reason.empty())
        reason = contact_coupling.check_tool_motion(old_load,
                                                    new_load,
                                                    newton_unknowns);
      return reason.empty() ? outcome : IncrementOutcome::diverged;
    }


    void
    FormingProblem::report_increment(const double       load_increment,
                                     const unsigned int iterations,
                                     const unsigned int cut_backs,
                                     const RunProgress &run)
    {
      const solver::LinearSolver::Statistics solver_statistics
        = linear_system->statistics();
      report.load_increment      = load_increment;
      report.iterations          = iterations;
      report.cut_backs           = cut_backs;
      report.force_residual      = progress.last_force_residual();
      report.contact_residual    = progress.last_contact_residual();
      report.plastic_points      = progress.plastic_points;
      report.contact_changes     = progress.contact_changes;
      report.assembly_time       = progress.assembly_time;
      report.solve_time          = progress.solve_time;
      report.factorized_unknowns = solver_statistics.factorized_unknowns;
      report.symbolic_analyses   = solver_statistics.symbolic_analyses
                                 - reported_solver_statistics.symbolic_analyses;
      reported_solver_statistics = solver_statistics;
      postprocessors.execute(*this);
      if (run.quiet)
        return;

      // Remaining time: the load still to go at the mean rate of this run
      // so far.
      const double elapsed = run.timer.wall_time();
      const double done    = committed.load - run.first_load;
      const double remaining
        = done > 0. ? elapsed / done * (final_load() - committed.load) : 0.;
      std::ostringstream line;
      line << "increment " << std::setw(4) << committed.increment_number
           << "  load " << std::setw(9) << format_load(committed.load)
           << "  iterations " << std::setw(2) << iterations << "  cut-backs "
           << cut_backs << std::scientific << std::setprecision(2)
           << "  residuals " << report.force_residual << " "
           << report.contact_residual << std::defaultfloat
           << "  plastic points " << report.plastic_points;
      if (contact_coupling.active())
        line << "  stick/slip " << contact_coupling.n_stick() << "/"
             << contact_coupling.n_slip();
      line << std::fixed << std::setprecision(3) << "  time "
           << increment_wall_time() << " s  elapsed " << format_seconds(elapsed)
           << "  remaining ~" << format_seconds(remaining);
      std::cout << line.str() << std::endl;
    }


    void
    FormingProblem::stop_cleanly(const std::string &reason)
    {
      std::string where = "; the results up to load "
                          + format_load(committed.load) + " are in "
                          + parameters.output.output_directory;
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
  } // namespace problem
} // namespace deepdraw
