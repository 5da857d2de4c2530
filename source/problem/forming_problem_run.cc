// The run of FormingProblem (doc/architecture.md, "Data flow of a run"):
// the stages one after the other, and in each the load stepping with
// cut-backs, the checks that no tool passed through the sheet, the
// post-processors after each converged increment, checkpoints and the
// clean stop on a signal (doc/user_guide.md §6).
#include <algorithm>
#include <cmath>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/output_directory.h>
#include <deepdraw/io/regular_file.h>
#include <deepdraw/io/writing_rank.h>
#include <deepdraw/parallel/ranks.h>
#include <deepdraw/parallel/run_agreement.h>
#include <deepdraw/problem/console_report.h>
#include <deepdraw/problem/forming_problem.h>
#include <deepdraw/solver/mumps_factorization.h>
#include <deepdraw/state/checkpoint.h>
#include <deepdraw/state/stop_request.h>
#include <filesystem>
#include <iostream>

namespace deepdraw
{
  namespace problem
  {
    namespace
    {
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
    FormingProblem::lock_output_directory(const RunOptions &options)
    {
      // A resume needs its checkpoint: a missing directory is reported by
      // restore_checkpoint, and not made.
      const std::string &directory = parameters.output.output_directory;
      std::error_code    error;
      if (!io::writes_files()
          || (options.resume
              && !std::filesystem::is_directory(directory, error)))
        return;
      // A named pipe in place of a table blocks the run that opens it
      // (D164): refused before the lock file is written.
      io::check_output_entries(directory);
      try
      {
        made_output_directory = !std::filesystem::exists(directory);
        std::filesystem::create_directories(directory);
        output_lock.acquire(directory,
                            "Output/Output directory",
                            options.quiet);
      }
      catch (const InputError &)
      {
        throw;
      }
      catch (const std::exception &failure)
      {
        if (made_output_directory)
          std::filesystem::remove_all(directory, error);
        throw InputError("Output/Output directory: cannot write results to '"
                         + directory + "': " + failure.what());
      }
    }


    void
    FormingProblem::start_run(const RunOptions &options)
    {
      // Before anything in the output directory is written or cut back.
      lock_output_directory(options);
      // Rank 0 alone made and locked the output directory, cuts back its
      // tables and opens them: the ranks go on together or not at all
      // (D199).
      parallel::agree_on_start();
      try
      {
        if (options.resume)
          restore_checkpoint(true);
        else if (const unsigned int penetrating = model->place_tools();
                 penetrating > 0 && !options.quiet)
          std::cout << "deepdraw: " << penetrating
                    << " sheet nodes start inside a tool; the first "
                       "increment pushes them out"
                    << std::endl;
      }
      catch (...)
      {
        // Nothing is written on an input error: a directory made for the
        // run goes again.
        if (made_output_directory)
        {
          output_lock.release();
          std::error_code ignored;
          std::filesystem::remove_all(parameters.output.output_directory,
                                      ignored);
        }
        throw;
      }
      parallel::agree_on_start();
      open_outputs(options.resume);
      parallel::agree_on_start();
      parallel::start_agreed();
      if (!options.resume)
        postprocessors.execute(*view);
      table_sizes = state::csv_table_sizes(parameters.output.output_directory);
    }


    void
    FormingProblem::open_outputs(const bool resume)
    {
      io::open_output_directory(
        parameters.output.output_directory,
        "Output/Output directory",
        [&]()
        {
          postprocessors.start(*view, resume);
          increments->open_log(parameters.output.output_directory, resume);
          adaptation->open(parameters.output.output_directory, resume);
        },
        made_output_directory);
    }


    void
    FormingProblem::run(const RunOptions &options)
    {
      ConsoleReport console(options.quiet);
      start_run(options);
      console.model(*view,
                    model->n_unknowns(),
                    fe::to_string(parameters.element.technology),
                    options.resume);
      const state::SimulationState &committed = model->state();
      while (true)
      {
        if (!committed.stage_completed)
        {
          run_stage(console);
          end_stage();
        }
        if (committed.stage + 1 >= parameters.stages.size())
          break;
        begin_stage(committed.stage + 1);
        console.stage(*view);
      }
      std::vector<std::string> summaries = postprocessors.summaries();
      // This process's counts (a resumed run's since its resume); with
      // `auto` only where a kept factorisation was used (D206). AMG never
      // reuses one, and `true` with AMG is refused at input.
      const auto statistics = model->linear_system().statistics();
      if (parameters.linear_solver.reuse
            == solver::LinearSolverParameters::Reuse::always
          || statistics.reused_solves > 0)
      {
        summaries.push_back(
          "linear solver: " + std::to_string(statistics.factorizations)
          + " factorisations, " + std::to_string(statistics.reused_solves)
          + " solves with a kept factorisation ("
          + std::to_string(statistics.gmres_iterations)
          + " GMRES iterations in all)");
      }
      if (statistics.single_precision_factorizations > 0)
        summaries.push_back(
          "linear solver: "
          + std::to_string(statistics.single_precision_factorizations)
          + " factorisations in single precision, refined by GMRES; "
          + std::to_string(statistics.single_precision_fallbacks)
          + " systems factorised again in double (D226)");
      if (parameters.linear_solver.iterative())
      {
        summaries.push_back(
          "linear solver: " + std::to_string(statistics.amg_hierarchies)
          + " AMG hierarchies, " + std::to_string(statistics.amg_solves)
          + " GMRES solves (" + std::to_string(statistics.gmres_iterations)
          + " iterations in all), " + std::to_string(statistics.amg_fallbacks)
          + " systems solved by MUMPS after GMRES failed, "
          + std::to_string(statistics.factorizations) + " factorisations");
      }
      console.finished(*view, wall_timer.wall_time(), summaries);
    }


    void
    FormingProblem::run_stage(const ConsoleReport &console)
    {
      const state::SimulationState &committed = model->state();
      const process::Stage         &stage     = model->stage();
      std::vector<double>           landings;
      for (const double load : postprocessors.requested_loads(*view))
        if (load > stage.start_load && load < stage.end_load)
          landings.push_back(load);
      solver::IncrementControl control(stage.load_stepping, landings);
      control.restore({committed.load, committed.next_increment});
      start_next_increment();
      while (!control.finished())
      {
        // mpirun passes a signal on to every rank, each at its own time:
        // they stop at the same increment (D199).
        if (const int signal_number
            = parallel::maximum(state::requested_stop_signal()))
          stop_cleanly("stopped by " + state::signal_name(signal_number));

        const double     old_load   = control.current_load();
        const double     new_load   = old_load + control.next_increment();
        unsigned int     iterations = 0;
        std::string      reason;
        IncrementOutcome outcome = IncrementOutcome::diverged;
        try
        {
          outcome
            = solve_checked_increment(old_load, new_load, iterations, reason);
        }
        catch (const solver::MumpsMemoryError &error)
        {
          // Memory, not the increment: no cut-back (D177).
          model->restore_trial_state();
          stop_cleanly(error.what());
        }
        if (outcome == IncrementOutcome::converged)
        {
          const unsigned int cut_backs
            = control.cut_backs_of_current_increment();
          control.accept(iterations);
          run_record.at_stage_end = control.finished();
          run_record.at_landing
            = control.finished() || is_landing(landings, new_load);
          complete_increment(new_load - old_load,
                             control.state().increment,
                             iterations,
                             cut_backs,
                             console);
          start_next_increment();
          continue;
        }
        console.cut_back(new_load, reason);
        model->restore_trial_state();
        if (!control.cut_back())
        {
          const bool too_small
            = control.next_increment() < stage.load_stepping.minimum_increment;
          stop_cleanly(
            "the increment from load " + format_load(old_load) + " to "
            + format_load(new_load) + " failed (" + reason + ") after "
            + std::to_string(control.cut_backs_of_current_increment())
            + " attempt(s), and "
            + (too_small ? "a further cut-back would go below Load "
                           "stepping/Minimum increment"
                         : "Load stepping/Maximum cut-backs is reached"));
        }
      }
    }


    void
    FormingProblem::start_next_increment()
    {
      // The times of an increment include its failed attempts (cut-backs):
      // they are reset only once it has converged.
      increments->start_timing();
      run_record.start_increment(model->contact().contact_time());
    }


    void
    FormingProblem::complete_increment(const double         load_increment,
                                       const double         next_increment,
                                       const unsigned int   iterations,
                                       const unsigned int   cut_backs,
                                       const ConsoleReport &console)
    {
      state::SimulationState &committed = model->state();
      increments->commit();
      ++committed.increment_number;
      committed.next_increment = next_increment;
      run_record.record_increment(load_increment,
                                  iterations,
                                  cut_backs,
                                  increments->progress(),
                                  model->linear_system().statistics(),
                                  model->contact().contact_time());
      postprocessors.execute(*view);
      console.increment(*view, iterations, cut_backs);

      // Adaptive refinement and re-equilibration at this load (D80), not
      // after the last increment of the run.
      const bool last = run_record.at_stage_end
                        && committed.stage + 1 == parameters.stages.size();
      const std::size_t refinements = adaptation->records().size();
      std::string       reason;
      if (!adapt_mesh(last, reason))
        stop_cleanly("the re-equilibration after refining the mesh at load "
                     + format_load(committed.load) + " failed (" + reason
                     + ")");
      if (adaptation->records().size() > refinements)
        console.refined(model->sheet().triangulation().n_active_cells(),
                        adaptation->records().back().iterations);
      table_sizes = state::csv_table_sizes(parameters.output.output_directory);
      // The end of a stage that another follows has its own checkpoint,
      // written once the stage has ended (end_stage): a resume then begins
      // the next stage with what it takes over (D150).
      const bool stage_checkpoint_follows
        = run_record.at_stage_end
          && committed.stage + 1 < parameters.stages.size();
      if (parameters.checkpoint.interval > 0
          && committed.increment_number % parameters.checkpoint.interval == 0
          && !stage_checkpoint_follows)
        save_checkpoint();
    }


    void
    FormingProblem::begin_stage(const unsigned int index)
    {
      try
      {
        model->begin_stage(index);
      }
      catch (const InputError &error)
      {
        stop_cleanly("stage " + std::to_string(index + 1) + " '"
                     + parameters.stages[index].name
                     + "' cannot begin: " + error.what());
      }
      increments->reset_unknowns();
      postprocessors.initialize(*view);
    }


    void
    FormingProblem::end_stage()
    {
      postprocessors.end_stage(*view);
      const std::string failure = model->end_stage();
      if (!failure.empty())
        stop_cleanly(failure);
      table_sizes = state::csv_table_sizes(parameters.output.output_directory);
      // A later run can begin the next stage from here (D101).
      if (model->state().stage + 1 < parameters.stages.size())
        save_checkpoint();
    }


    FormingProblem::IncrementOutcome
    FormingProblem::solve_checked_increment(const double  old_load,
                                            const double  new_load,
                                            unsigned int &iterations,
                                            std::string  &reason)
    {
      const contact::ContactCoupling &contact = model->contact();
      // A tool that moves farther than the search distance in one
      // increment can pass through the sheet unseen (D56).
      reason = contact.active() ? contact.check_tool_motion(old_load, new_load)
                                : std::string();
      if (!reason.empty())
        return IncrementOutcome::diverged;
      const IncrementOutcome outcome
        = increments->solve(old_load, new_load, iterations);
      reason = solver::describe(outcome);
      if (outcome != IncrementOutcome::converged || !contact.active())
        return outcome;
      reason = contact.check_tool_sides(
        model->sheet().triangulation().get_vertices(),
        increments->unknowns(),
        parameters.geometry.thickness);
      if (reason.empty())
        reason = contact.check_tool_motion(old_load,
                                           new_load,
                                           increments->unknowns());
      return reason.empty() ? outcome : IncrementOutcome::diverged;
    }


    void
    FormingProblem::stop_cleanly(const std::string &reason)
    {
      std::string where = "; the results up to load "
                          + format_load(model->state().load) + " are in "
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
