// The forming problem (doc/architecture.md): the stages of the process, the
// increments of each with their load stepping, and the Newton iterations of
// each increment through the solver::NewtonSystem this class implements, on
// the model of SheetModel; after every converged increment the
// post-processors read the model through SimulationView.
#ifndef deepdraw_problem_forming_problem_h
#define deepdraw_problem_forming_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deepdraw/adaptivity/mesh_adaptation.h>
#include <deepdraw/postprocess/manager.h>
#include <deepdraw/problem/console_report.h>
#include <deepdraw/problem/model_parameters.h>
#include <deepdraw/problem/newton_log.h>
#include <deepdraw/problem/sheet_model.h>
#include <deepdraw/problem/simulation_view.h>
#include <deepdraw/solver/newton_increment.h>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace deepdraw
{
  namespace problem
  {
    using namespace dealii;

    // Thrown when the run cannot continue; the message says why.
    class RunFailure : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    // How run() starts and reports.
    struct RunOptions
    {
      // Continue from the checkpoint in the output directory.
      bool resume = false;
      // Print only the summary line, not one line per increment.
      bool quiet = false;
    };

    class FormingProblem : private solver::NewtonSystem
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      // Parses and checks all parameters (throws InputError) and sets the
      // model up for the first stage; writes nothing. Relative file names
      // in the parameters (tool files) are taken from input_directory.
      explicit FormingProblem(ParameterHandler  &prm,
                              const std::string &input_directory = ".");

      // Runs every stage, writing results as increments converge. Throws
      // RunFailure if an increment cannot be completed or a signal asks to
      // stop (after writing a checkpoint); what was written until then
      // stays valid. Throws InputError if the start is unusable (a tool
      // inside the blank, a checkpoint of another model).
      void
      run(const RunOptions &options = RunOptions());

      // What the post-processors read (tests read it too).
      const postprocess::SimulationAccess &
      access() const;

      // For tests: the prescribed increments and tool positions of the
      // increment [old_load, new_load], as an increment sets them, so that
      // evaluate_residual() sees the same equations.
      void
      prepare_increment(double old_load, double new_load);
      // The residual r(x) of all equations (displacement rows f_int - P,
      // contact rows F_sup, tool rows) for the Newton unknowns x (as
      // SimulationState::converged_solution), from the current
      // configuration and committed history, without constraints; with
      // tangent != nullptr also dr/dx. False if a point failed.
      bool
      evaluate_residual(const Vector<double> &unknowns,
                        Vector<double>       &residual,
                        FullMatrix<double>   *tangent);
      // Assembles residual and tangent for the unknowns without
      // constraints, as one Newton iteration does (benchmarks).
      bool
      assemble_system(const Vector<double> &unknowns);
      // Quadrature points that yielded in the last assembly.
      unsigned int
      last_plastic_points() const;
      // Relative force residuals of the last increment's Newton checks.
      const std::vector<double> &
      last_residuals() const;
      // The refinements of an adaptive run so far.
      const std::vector<adaptivity::RefinementRecord> &
      refinement_records() const;

    private:
      using IncrementOutcome = solver::IncrementOutcome;

      // The run (forming_problem_run.cc).
      void
      start_run(const RunOptions &options);
      // Opens the outputs; a failure is an input error, the directory made
      // for them removed again.
      void
      open_outputs(bool resume);
      void
      run_stage(const ConsoleReport &console);
      // Stage `index` begins, or the run stops cleanly if it cannot.
      void
      begin_stage(unsigned int index);
      void
      end_stage();
      // solve_increment() and the checks that no tool passed through the
      // sheet (D56); reason says why an increment failed.
      IncrementOutcome
      solve_checked_increment(double        old_load,
                              double        new_load,
                              unsigned int &iterations,
                              std::string  &reason);
      // The post-processors of a converged increment.
      void
      report_increment(double       load_increment,
                       unsigned int iterations,
                       unsigned int cut_backs);
      // Writes a checkpoint of the last converged state and throws
      // RunFailure(reason).
      [[noreturn]] void
      stop_cleanly(const std::string &reason);
      void
      save_checkpoint() const;
      // The checkpoint of the output directory: checked against the
      // parameters, the model restored, the tables cut back to their
      // sizes then (forming_problem_checkpoint.cc).
      void
      restore_checkpoint();
      // Adaptive refinement after a converged increment (D80): false if
      // the re-equilibration failed (reason says why).
      bool
      adapt_mesh(bool last_increment, std::string &reason);
      // One Newton solve at the current load without a load increment.
      IncrementOutcome
      reequilibrate(unsigned int &iterations);

      // One increment (forming_problem_newton.cc).
      IncrementOutcome
      solve_increment(double        old_load,
                      double        new_load,
                      unsigned int &iterations);
      // The unknowns of the increment's start: du = 0, contact forces and
      // tool positions converged.
      void
      start_from_converged_state();
      IncrementOutcome
      assemble(const Vector<double>            &unknowns,
               const AffineConstraints<double> &constraints,
               bool                             with_matrix);

      // solver::NewtonSystem (doc/theory.md §5): the increment's Newton
      // unknowns are newton_unknowns.
      IncrementOutcome
      assemble_at(const Vector<double> &x, bool predictor) override;
      bool
      solve_correction(Vector<double> &correction, bool predictor) override;
      bool
      is_prescribed(types::global_dof_index i) const override;
      solver::ResidualMeasures
      residual_measures() const override;
      double
      merit() const override;
      unsigned int
      state_changes() const override;
      double
      correction_norm(const Vector<double> &correction) const override;
      double
      relative_correction(const Vector<double> &x,
                          double                correction_norm) const override;
      void
      record_iteration(unsigned int                    iterations,
                       const solver::ResidualMeasures &residuals,
                       double relative_correction) override;

      // Wall time since the problem was constructed: the reported run time
      // includes the set-up (mesh, tools, pairs), which a tool of many
      // patches makes long.
      Timer wall_timer;

      ModelParameters                             parameters;
      std::unique_ptr<SheetModel>                 model;
      postprocess::Manager                        postprocessors;
      NewtonLog                                   newton_log;
      std::unique_ptr<adaptivity::MeshAdaptation> adaptation;
      RunRecord                                   run_record;
      std::unique_ptr<SimulationView>             view;

      // The increment being solved: its Newton unknowns [du | lambda | z],
      // its loads and the progress of its Newton iterations.
      Vector<double> newton_unknowns;
      double         start_load  = 0.;
      double         target_load = 0.;
      NewtonProgress progress;
      // The linear solver's counts at the last row of statistics.csv.
      solver::LinearSolver::Statistics reported_solver_statistics;
      // Sizes of the CSV tables after the last converged increment's rows
      // (a checkpoint leaves out the rows of later failed attempts).
      std::vector<std::pair<std::string, std::uintmax_t>> table_sizes;
    };
  } // namespace problem
} // namespace deepdraw

#endif
