// The forming problem (doc/architecture.md): the stages of the process and
// the increments of each with their load stepping, each solved by an
// IncrementSolver on the model of SheetModel; after every converged
// increment the post-processors read the model through SimulationView.
#ifndef deepdraw_problem_forming_problem_h
#define deepdraw_problem_forming_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deepdraw/adaptivity/mesh_adaptation.h>
#include <deepdraw/io/output_lock.h>
#include <deepdraw/postprocess/manager.h>
#include <deepdraw/problem/console_report.h>
#include <deepdraw/problem/increment_solver.h>
#include <deepdraw/problem/model_parameters.h>
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

    class FormingProblem
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

      // --check --resume: the checkpoint of the output directory verified
      // as a resume verifies it (D160, D161): throws InputError naming the
      // checkpoint and what is wrong; writes nothing.
      void
      check_resume();

      // What the post-processors read (tests read it too).
      const postprocess::SimulationAccess &
      access() const;

      // The solver of the increments (tests and benchmarks evaluate the
      // equations through it).
      IncrementSolver &
      increment_solver();
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
      // Before an increment's first attempt: its times start from zero.
      void
      start_next_increment();
      // Commits the converged increment and reports it (post-processors,
      // console), then refines the mesh and writes a checkpoint where
      // asked.
      void
      complete_increment(double               load_increment,
                         double               next_increment,
                         unsigned int         iterations,
                         unsigned int         cut_backs,
                         const ConsoleReport &console);
      // Stage `index` begins, or the run stops cleanly if it cannot.
      void
      begin_stage(unsigned int index);
      void
      end_stage();
      // The increment solved and the checks that no tool passed through the
      // sheet (D56); reason says why an increment failed.
      IncrementOutcome
      solve_checked_increment(double        old_load,
                              double        new_load,
                              unsigned int &iterations,
                              std::string  &reason);
      // Writes a checkpoint of the last converged state and throws
      // RunFailure(reason).
      [[noreturn]] void
      stop_cleanly(const std::string &reason);
      void
      save_checkpoint() const;
      // The checkpoint of the output directory, verified whole (checksum,
      // fields, parameters, input files, the model's sizes, the
      // post-processors' data, the tables) and restored in memory; the
      // tables are cut back to their sizes then only if cut_tables, after
      // every check (D160).
      void
      restore_checkpoint(bool cut_tables);
      // The files the model reads besides the prm, by the parameter that
      // names each: tool, outline and mesh files.
      std::vector<std::pair<std::string, std::string>>
      input_file_names() const;
      // The output directory made if it is missing (not on a resume) and
      // locked for this run (D162).
      void
      lock_output_directory(const RunOptions &options);
      // Adaptive refinement after a converged increment (D80): false if
      // the re-equilibration failed (reason says why).
      bool
      adapt_mesh(bool last_increment, std::string &reason);

      // Wall time since the problem was constructed: the reported run time
      // includes the set-up (mesh, tools, pairs), which a tool of many
      // patches makes long.
      Timer wall_timer;

      ModelParameters                             parameters;
      std::unique_ptr<SheetModel>                 model;
      postprocess::Manager                        postprocessors;
      std::unique_ptr<adaptivity::MeshAdaptation> adaptation;
      RunRecord                                   run_record;
      std::unique_ptr<SimulationView>             view;
      std::unique_ptr<IncrementSolver>            increments;
      // Sizes of the CSV tables after the last converged increment's rows
      // (a checkpoint leaves out the rows of later failed attempts).
      std::vector<std::pair<std::string, std::uintmax_t>> table_sizes;
      // The digests of the input files when the run began (D161).
      std::vector<state::InputFile> input_files;
      // The run's hold on its output directory, and whether the directory
      // was made for it.
      io::OutputLock output_lock;
      bool           made_output_directory = false;
    };
  } // namespace problem
} // namespace deepdraw

#endif
