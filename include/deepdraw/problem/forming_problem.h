// The forming problem: owns the blank's mesh, the degrees of freedom, the
// quadrature-point history, and drives the increments (doc/architecture.md).
//
// Unknowns are ordered in blocks: displacements first, then the contact
// forces and the tool positions of force-controlled tools, all in one
// unsymmetric system solved by a direct solver (doc/theory.md §7). One
// increment's Newton iterations run in solver::NewtonIncrement through the
// solver::NewtonSystem this class implements.
#ifndef deepdraw_problem_forming_problem_h
#define deepdraw_problem_forming_problem_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/fe/cell_geometry.h>
#include <deepdraw/fe/element_technology.h>
#include <deepdraw/fe/hexahedron_element.h>
#include <deepdraw/fe/quadrature_point_update.h>
#include <deepdraw/fe/vertex_parents.h>
#include <deepdraw/geometry/square_cup_tools.h>
#include <deepdraw/io/csv_file.h>
#include <deepdraw/io/output_parameters.h>
#include <deepdraw/io/pvd_record.h>
#include <deepdraw/material/elasto_plasticity.h>
#include <deepdraw/material/material_parameters.h>
#include <deepdraw/problem/adaptivity_parameters.h>
#include <deepdraw/problem/blank_geometry.h>
#include <deepdraw/problem/checkpoint.h>
#include <deepdraw/problem/contact_coupling.h>
#include <deepdraw/problem/earing_profile.h>
#include <deepdraw/problem/prescribed_displacements.h>
#include <deepdraw/problem/process_parameters.h>
#include <deepdraw/problem/process_tables.h>
#include <deepdraw/problem/sheet_thickness.h>
#include <deepdraw/problem/simulation_state.h>
#include <deepdraw/solver/increment_control.h>
#include <deepdraw/solver/linear_solver.h>
#include <deepdraw/solver/newton_increment.h>
#include <deepdraw/solver/newton_parameters.h>
#include <memory>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace problem
  {
    using namespace dealii;
    using fe::QuadraturePointHistory;

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

      // Parses and checks all parameters (throws InputError); writes nothing.
      // Relative file names in the parameters (tool files) are taken from
      // input_directory.
      explicit FormingProblem(ParameterHandler  &prm,
                              const std::string &input_directory = ".");

      // Runs all increments, writing results as they converge. Throws
      // RunFailure if an increment cannot be completed or a signal asks to
      // stop (after writing a checkpoint); what was written until then
      // stays valid. Throws InputError if the start is unusable (a tool
      // inside the blank, a checkpoint of another model).
      void
      run(const RunOptions &options = RunOptions());

      // Sets the prescribed displacements and the tool positions of the
      // increment [old_load, new_load] as solve_increment() does, so that
      // evaluate_residual() sees the same equations (tests).
      void
      prepare_increment(double old_load, double new_load);
      // The Newton unknowns of the last converged increment: displacement
      // increment, then contact forces and tool positions.
      const Vector<double> &
      get_newton_unknowns() const;

      // Residual r(x) of all equations (displacement rows f_int - P,
      // contact rows F_sup, tool rows) for the Newton unknowns x (see
      // get_newton_unknowns), measured from the current configuration and
      // committed history, without constraints; with tangent != nullptr
      // also dr/dx. Used by the tangent verification tests.
      bool
      evaluate_residual(const Vector<double> &unknowns,
                        Vector<double>       &residual,
                        FullMatrix<double>   *tangent);

      // Assembles residual and tangent into the internal sparse system for
      // the increment du without constraints (what one Newton iteration
      // assembles); returns false if a point failed. For benchmarks.
      bool
      assemble_system(const Vector<double> &unknowns);

      const DoFHandler<3> &
      get_dof_handler() const;
      const Vector<double> &
      get_total_displacement() const;
      // Initial position of every vertex.
      const std::vector<Point<3>> &
      get_initial_vertices() const;
      // Cauchy stress averaged over each cell, by active cell index.
      std::vector<Tensor<2, 3>>
      cell_average_cauchy_stress() const;
      const std::vector<QuadraturePointHistory> &
      get_history() const;
      // The committed state (what a restart or a mesh change carries).
      const SimulationState &
      get_state() const;
      // Sum of the internal forces over the dofs of a face (reaction).
      Tensor<1, 3>
      face_reaction(unsigned int boundary_id) const;
      // Internal nodal forces f_int of the last assembly (after run(): of
      // the last converged increment); at constrained dofs these are the
      // nodal reactions, e.g. to compute a moment on a face.
      const Vector<double> &
      get_internal_force() const;
      // Quadrature points that yielded in the last assembly.
      unsigned int
      last_plastic_points() const;
      // Volume of the sheet in the current configuration (mm³).
      double
      sheet_volume() const;
      // Current thickness at the initial in-plane position (X, Y) of every
      // vertex (SheetThickness, doc/theory.md §6).
      const std::vector<double> &
      get_vertex_thickness() const;
      // The thickness measurement of the sheet (its vertex normals of the
      // current configuration).
      const SheetThickness &
      get_sheet_thickness() const;

      // Newton history of the last increment: relative force residuals.
      const std::vector<double> &
      last_residuals() const;

      // Contact with the tools (inactive if no tool is declared).
      const ContactCoupling &
      get_contact() const;
      // Number of displacement unknowns (they come first in the system).
      types::global_dof_index
      n_displacement_dofs() const;

      // One mesh refinement of an adaptive run (adaptivity.csv,
      // forming_problem_adaptivity.cc).
      struct RefinementRecord
      {
        unsigned int cycle;
        unsigned int increment;
        double       load;
        unsigned int cells_before;
        unsigned int cells_after;
        unsigned int hanging_vertices;
        // Force and contact residuals of the transferred state, before the
        // re-equilibration, and its Newton iterations and last residual.
        double       initial_force_residual;
        double       initial_contact_residual;
        unsigned int iterations;
        double       force_residual;
        double       wall_time;
      };
      const std::vector<RefinementRecord> &
      refinement_records() const;

    private:
      using IncrementOutcome = solver::IncrementOutcome;

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

      // Checks that need several subsections (forming_problem_input.cc);
      // throws InputError.
      void
      check_input() const;
      void
      setup_system();
      // Dofs, hanging-node constraints, prescribed dofs, contact pairs and
      // the sparsity of the current mesh (after setup_system or a
      // refinement).
      void
      setup_dofs();
      // SheetThickness on the current mesh, every vertex located on it, and
      // the profile and rim points (end of setup_dofs).
      void
      set_up_thickness_measurement();
      void
      add_hanging_node_constraints(
        AffineConstraints<double> &constraints) const;
      void
      update_cell_geometry();
      // cell_matrix_positions for the current dofs and sparsity pattern.
      void
      find_cell_matrix_positions();
      void
      set_up_prescribed_increment(double old_load, double new_load);
      // Assembles f_int, the residual (rhs = -r on free dofs) and, if
      // requested, the tangent; trial history from du.
      IncrementOutcome
      assemble(const Vector<double>            &unknowns,
               const AffineConstraints<double> &constraints,
               bool                             assemble_matrix);
      // Trial element-internal unknowns: the committed ones times ratio.
      void
      start_enhanced_parameters(double ratio);
      IncrementOutcome
      solve_increment(double        old_load,
                      double        new_load,
                      unsigned int &iterations);
      void
      commit_increment();
      // Adds the displacement block of newton_unknowns to the total
      // displacement and moves the mesh by it (updated Lagrangian).
      void
      move_mesh();

      // Adaptive refinement (forming_problem_adaptivity.cc, doc/theory.md
      // §8): after the converged increment, if it is due, flags cells by the
      // indicator, refines and transfers the state, rebuilds the system and
      // re-equilibrates at the same load. Returns false if the
      // re-equilibration failed (reason says why).
      bool
      adapt_mesh(bool last_increment, std::string &reason);
      // The indicator of Adaptivity/Indicator per active cell, scaled so
      // that the cells to refine are those above 1 (value / threshold;
      // the larger of the two for the combined indicator, D95).
      std::vector<double>
      scaled_refinement_indicator() const;
      // Refines the flagged cells and carries the state over (history,
      // displacements, contact pairs and multipliers).
      void
      refine_and_rebuild();
      // After a refinement that added the vertices from n_old_vertices on:
      // their parents among the blank's vertices and their initial
      // positions, interpolated from those (parents: fe::vertex_parents).
      void
      add_blank_parents(const std::vector<fe::VertexParents> &parents,
                        unsigned int                          n_old_vertices);
      // A resume of an adaptive run: the refinement cycles of the
      // checkpoint on the blank's mesh, then the dofs and pairs (D84).
      void
      replay_refinements(
        const std::vector<std::vector<std::array<int, 3>>> &cycles);
      // One Newton solve at the current load without a load increment.
      IncrementOutcome
      reequilibrate(unsigned int &iterations);
      void
      compute_thickness();
      // The loads the increments land on (VTU outputs, thickness profiles).
      std::vector<double>
      landing_loads() const;
      // The initial state (or the checkpoint's) and the opened outputs.
      void
      start_run(const RunOptions &options);
      // solve_increment() and the checks that no tool passed through the
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
      // One converged increment as statistics.csv and the console see it.
      struct IncrementRecord
      {
        double       load_increment;
        unsigned int iterations;
        unsigned int cut_backs;
        double       output_time;
        double       search_time;
        double       wall_time;
      };
      void
      write_statistics_row(const IncrementRecord &record);
      void
      print_increment_line(const IncrementRecord &record,
                           double                 elapsed,
                           double                 remaining) const;
      // Checkpoint of the committed state (forming_problem_checkpoint.cc).
      void
      save_checkpoint() const;
      // Restores the checkpoint of the output directory; cuts the CSV
      // tables back to their sizes at the checkpoint.
      void
      restore_checkpoint();
      // Opens the CSV tables (appending to them on a resume) and the PVD.
      void
      open_output_files(bool resume);
      void
      open_output_tables(bool resume);
      void
      write_vtu(double load);
      void
      write_increment_tables(double load);
      // thickness_OX/OY/OD_<travel>mm.csv and earing_<travel>mm.csv at a
      // requested travel.
      void
      write_thickness_profiles(double travel);
      // The points of the thickness profiles and the rim.
      void
      set_up_thickness_profiles();

      // Wall time since the problem was constructed: the reported run time
      // includes the set-up (mesh, tools, pairs), which a tool of many
      // patches makes long.
      Timer wall_timer;

      // Parameters
      BlankGeometry                      geometry;
      ProcessParameters                  process_parameters;
      material::MaterialParameters       material_parameters;
      PrescribedDisplacements            prescribed;
      solver::IncrementControlParameters increment_parameters;
      solver::NewtonParameters           newton_parameters;
      solver::LinearSolverParameters     linear_solver_parameters;
      io::OutputParameters               output_parameters;
      geometry::SquareCupToolParameters  square_cup_tool_parameters;
      ContactCoupling                    contact;
      fe::ElementParameters              element_parameters;
      CheckpointParameters               checkpoint_parameters;
      AdaptivityParameters               adaptivity_parameters;
      // All parameters, flattened (a checkpoint refuses another model).
      std::string parameter_listing;

      std::unique_ptr<material::ElastoPlasticity> material;
      std::unique_ptr<fe::HexahedronElement>      element;

      // Discretisation
      Triangulation<3>                                    triangulation;
      std::vector<Point<3>>                               initial_vertices;
      FESystem<3>                                         fe;
      DoFHandler<3>                                       dof_handler;
      FE_Q<3>                                             fe_scalar;
      DoFHandler<3>                                       scalar_dof_handler;
      std::vector<std::array<types::global_dof_index, 3>> vertex_dofs;
      std::vector<Point<3>>                               dof_initial_position;
      std::vector<unsigned int>                           dof_component;
      std::vector<fe::CellGeometry>                       cell_geometry;
      // Per active cell, where the entries of its 24 x 24 matrix (row-major,
      // local order) lie in system_matrix's values: the serial copier adds
      // through them instead of searching the rows (D99). Rebuilt with the
      // sparsity pattern.
      std::vector<unsigned int>                           cell_matrix_positions;
      std::array<std::vector<types::global_dof_index>, 6> face_dofs;
      // Mean in-plane element size of the blank's mesh (contact
      // augmentation, D34, D82).
      double blank_element_size = 1.;
      // After adaptive refinement: for every vertex, the blank's vertices it
      // is interpolated from (empty before the first refinement).
      std::vector<fe::VertexParents> blank_vertex_parents;
      // Thickness of the sheet at reference points, and where each
      // vertex's initial (X, Y) lies on its surfaces.
      std::unique_ptr<SheetThickness>       sheet_thickness;
      std::vector<SheetThickness::Location> vertex_locations;
      // The OX, OY, OD profiles: name, initial distance s0 from the origin
      // and location of each point (doc/user_guide.md §3.1).
      struct ThicknessProfile
      {
        std::string                                              name;
        std::vector<std::pair<double, SheetThickness::Location>> points;
      };
      std::vector<ThicknessProfile> thickness_profiles;
      // Rim of the blank for earing_<travel>mm.csv.
      EaringProfile earing;

      // Constrained dofs with their prescribed displacement entry.
      std::vector<
        std::pair<types::global_dof_index, const PrescribedDisplacement *>>
        prescribed_dofs;
      // Contact-force components along prescribed displacement components
      // (held at zero, see ContactCoupling::multiplier_blocks).
      std::vector<types::global_dof_index> constrained_multipliers;
      // Hanging vertices of a refined mesh (closed; empty on the blank's
      // mesh), part of both constraint sets below.
      AffineConstraints<double> hanging_node_constraints;
      AffineConstraints<double> homogeneous_constraints;
      AffineConstraints<double> predictor_constraints;

      SparsityPattern      sparsity_pattern;
      SparseMatrix<double> system_matrix;
      Vector<double>       system_rhs;
      Vector<double>       internal_force;
      // The Newton unknowns of the increment, [du | lambda | z]: the
      // displacement increment (first n_displacement_dofs entries), then
      // the contact forces and the tool positions (absolute values).
      Vector<double> newton_unknowns;
      double         start_load  = 0.;
      double         target_load = 0.;

      // What a restart or a mesh change must carry: committed history,
      // enhanced parameters, displacement, last Newton unknowns, load.
      SimulationState state;
      // Trial values of the increment being solved (restored from state on
      // a cut-back).
      std::vector<QuadraturePointHistory> trial_history;
      std::vector<fe::EnhancedParameters> trial_enhanced_parameters;


      std::unique_ptr<solver::LinearSolver> linear_solver;
      // The solver's counts when the last statistics row was written.
      solver::LinearSolver::Statistics reported_solver_statistics;

      // Results
      std::vector<double> vertex_thickness;
      std::vector<double> residual_history;
      std::vector<double> contact_residual_history;
      unsigned int        contact_changes = 0;
      // Of the last assembly alone (NewtonSystem::state_changes, D91).
      unsigned int last_assembly_changes = 0;
      // Contact state changes already written to newton.csv.
      unsigned int changes_reported = 0;
      unsigned int n_plastic_points = 0;

      // Timers of the current increment (seconds)
      double assembly_time = 0.;
      double solve_time    = 0.;

      // Output
      std::unique_ptr<io::PvdRecord> pvd;
      io::CsvFile                    statistics_file;
      io::CsvFile                    newton_file;
      io::CsvFile                    reactions_file;
      io::CsvFile                    tools_file;
      // adaptivity.csv: one row per refinement (adaptive runs only).
      io::CsvFile                   adaptivity_file;
      std::vector<RefinementRecord> refinement_history;
      // newton.csv rows of a re-equilibration belong to the increment just
      // converged, not the next.
      bool                      reequilibrating = false;
      std::vector<unsigned int> reaction_faces;
      unsigned int              output_step = 0;
      // The steps of solution.pvd restored from a checkpoint.
      std::vector<io::PvdRecord::Entry> resumed_pvd_steps;
      // Sizes of the CSV tables after the last converged increment's rows
      // (a checkpoint leaves out the rows of later failed attempts).
      std::vector<std::pair<std::string, std::uintmax_t>> committed_table_sizes;

      // punch_force.csv, draw_in.csv (runs with tools), and the travels
      // of the thickness profiles within the run.
      ProcessTables       process_tables;
      std::vector<double> profile_travels;
    };
  } // namespace problem
} // namespace deepdraw

#endif
