// The forming problem (doc/architecture.md): the stages of the process, the
// increments of each, and the Newton iterations of each increment through
// the solver::NewtonSystem this class implements. It owns the model (the
// sheet's discretisation, the contact coupling, the Newton system, the
// committed state) and hands it to the post-processors read-only
// (postprocess::SimulationAccess).
//
// Unknowns are ordered in blocks: displacements first, then the contact
// forces and the tool positions of force-controlled tools, all in one
// unsymmetric system (doc/theory.md §7).
#ifndef deepdraw_problem_forming_problem_h
#define deepdraw_problem_forming_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deepdraw/adaptivity/mesh_adaptation.h>
#include <deepdraw/contact/contact_coupling.h>
#include <deepdraw/discretisation/newton_constraints.h>
#include <deepdraw/discretisation/sheet_discretisation.h>
#include <deepdraw/discretisation/thickness_measurement.h>
#include <deepdraw/fe/hexahedron_element.h>
#include <deepdraw/linear_algebra/newton_linear_system.h>
#include <deepdraw/material/hill_plasticity.h>
#include <deepdraw/postprocess/manager.h>
#include <deepdraw/postprocess/simulation_access.h>
#include <deepdraw/problem/model_parameters.h>
#include <deepdraw/problem/newton_log.h>
#include <deepdraw/solver/increment_control.h>
#include <deepdraw/solver/newton_increment.h>
#include <deepdraw/state/simulation_state.h>
#include <memory>
#include <stdexcept>
#include <string>
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

    class FormingProblem : private solver::NewtonSystem,
                           private postprocess::SimulationAccess
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

      // For tests: sets the prescribed displacements and the tool positions
      // of the increment [old_load, new_load] as an increment does, so that
      // evaluate_residual() sees the same equations.
      void
      prepare_increment(double old_load, double new_load);
      // The residual r(x) of all equations (displacement rows f_int - P,
      // contact rows F_sup, tool rows) for the Newton unknowns x (see
      // SimulationState::converged_solution), measured from the current
      // configuration and committed history, without constraints; with
      // tangent != nullptr also dr/dx. Returns false if a point failed.
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

      // Set-up (forming_problem.cc).
      // The Newton system of the current mesh and stage: the contact pairs
      // of the tools that take part, the constraints, the linear system,
      // the thickness measurement; the post-processors set up again.
      void
      set_up_system();
      // The initial state on the blank's mesh.
      void
      initialize_state();
      // Stage `index` begins (not the first): the tools and constraints of
      // the stage, the contact state carried over (D101).
      void
      begin_stage(unsigned int index);
      const process::Stage &
      stage() const;
      // The committed state of a converged increment.
      void
      commit_increment();
      // Adds the displacement block of newton_unknowns to the total
      // displacement and moves the mesh by it (updated Lagrangian).
      void
      move_mesh();

      // The run (forming_problem_run.cc), as the console reports it: since
      // when, from which load, and whether a line per increment.
      struct RunProgress
      {
        Timer  timer;
        bool   quiet      = false;
        double first_load = 0.;
      };
      void
      start_run(const RunOptions &options);
      void
      run_stage(const RunProgress &run);
      void
      end_stage();
      // solve_increment() and the checks that no tool passed through the
      // sheet (D56); reason says why an increment failed.
      IncrementOutcome
      solve_checked_increment(double        old_load,
                              double        new_load,
                              unsigned int &iterations,
                              std::string  &reason);
      // The outputs of a converged increment and its console line.
      void
      report_increment(double             load_increment,
                       unsigned int       iterations,
                       unsigned int       cut_backs,
                       const RunProgress &run);
      // Writes a checkpoint of the last converged state and throws
      // RunFailure(reason).
      [[noreturn]] void
      stop_cleanly(const std::string &reason);
      void
      save_checkpoint() const;
      // The checkpoint of the output directory: the stage's set-up, the
      // state, the output tables cut back to their sizes then.
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
      // Trial element-internal unknowns: the committed ones times ratio.
      void
      start_enhanced_parameters(double ratio);
      // Assembles f_int, the residual (rhs = -r on free dofs) and, if
      // requested, the tangent at the unknowns; trial history from du.
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

      // postprocess::SimulationAccess (forming_problem_access.cc).
      const blank::BlankGeometry &
      blank() const override;
      const discretisation::SheetDiscretisation &
      sheet() const override;
      const discretisation::ThicknessMeasurement &
      thickness() const override;
      const material::HillPlasticity &
      material() const override;
      const contact::ContactCoupling &
      contact() const override;
      const state::SimulationState &
      state() const override;
      const Vector<double> &
      internal_force() const override;
      const std::vector<unsigned int> &
      reaction_faces() const override;
      const std::vector<process::Stage> &
      stages() const override;
      unsigned int
      stage_index() const override;
      bool
      stage_finished() const override;
      bool
      landed() const override;
      double
      final_load() const override;
      const postprocess::IncrementReport &
      increment_report() const override;
      double
      increment_wall_time() const override;
      double
      output_time() const override;
      const std::string &
      output_directory() const override;

      // Wall time since the problem was constructed: the reported run time
      // includes the set-up (mesh, tools, pairs), which a tool of many
      // patches makes long.
      Timer wall_timer;

      ModelParameters                                     parameters;
      std::unique_ptr<material::HillPlasticity>           material_model;
      std::unique_ptr<fe::HexahedronElement>              element;
      discretisation::SheetDiscretisation                 discretisation;
      discretisation::ThicknessMeasurement                thickness_measurement;
      discretisation::NewtonConstraints                   constraints;
      contact::ContactCoupling                            contact_coupling;
      std::unique_ptr<linear_algebra::NewtonLinearSystem> linear_system;
      // The faces with a prescribed displacement in some stage.
      std::vector<unsigned int> faces_with_reactions;

      // What a restart or a mesh change must carry (committed when an
      // increment converges), and the trial values of the increment being
      // solved (restored from it on a cut-back).
      state::SimulationState                  committed;
      std::vector<fe::QuadraturePointHistory> trial_history;
      std::vector<fe::EnhancedParameters>     trial_enhanced_parameters;

      // The increment being solved: its Newton unknowns [du | lambda | z]
      // (du first, then contact forces and tool positions), its loads, the
      // internal forces of the last assembly and its progress.
      Vector<double> newton_unknowns;
      Vector<double> internal_forces;
      double         start_load  = 0.;
      double         target_load = 0.;
      NewtonProgress progress;
      // The run's figures.
      postprocess::IncrementReport     report;
      solver::LinearSolver::Statistics reported_solver_statistics;
      Timer                            increment_timer;
      // The last increment landed on a requested load / ended its stage.
      bool at_landing   = false;
      bool at_stage_end = false;

      // Sizes of the CSV tables after the last converged increment's rows
      // (a checkpoint leaves out the rows of later failed attempts).
      std::vector<std::pair<std::string, std::uintmax_t>> table_sizes;
      postprocess::Manager                                postprocessors;
      NewtonLog                                           newton_log;
      std::unique_ptr<adaptivity::MeshAdaptation>         adaptation;
    };
  } // namespace problem
} // namespace deepdraw

#endif
