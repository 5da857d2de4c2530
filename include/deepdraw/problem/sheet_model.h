// The discretised model of a forming process (doc/architecture.md): the
// sheet's mesh and dofs, its material and element, the tools and their
// contact coupling, the constraints and the Newton system of the current
// stage, and the committed state with the trial state of the increment
// being solved. It keeps these consistent when the stage changes, an
// increment converges, the mesh is refined or a checkpoint is restored;
// FormingProblem drives it.
#ifndef deepdraw_problem_sheet_model_h
#define deepdraw_problem_sheet_model_h

#include <deal.II/base/parameter_handler.h>
#include <deepdraw/adaptivity/mesh_adaptation.h>
#include <deepdraw/contact/contact_coupling.h>
#include <deepdraw/discretisation/newton_constraints.h>
#include <deepdraw/discretisation/sheet_discretisation.h>
#include <deepdraw/discretisation/thickness_measurement.h>
#include <deepdraw/fe/hexahedron_element.h>
#include <deepdraw/linear_algebra/newton_linear_system.h>
#include <deepdraw/material/elasto_plasticity.h>
#include <deepdraw/problem/model_parameters.h>
#include <deepdraw/problem/viscous_stabilization.h>
#include <deepdraw/state/checkpoint.h>
#include <deepdraw/state/simulation_state.h>
#include <memory>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace problem
  {
    using namespace dealii;

    // What one assembly found.
    struct AssemblyResult
    {
      fe::ElementStatus status         = fe::ElementStatus::ok;
      unsigned int      plastic_points = 0;
      // Elements condensed with unconverged enhanced parameters (D189).
      unsigned int pending_elements = 0;
      // Contact pairs whose state changed (NewtonSystem::state_changes).
      unsigned int contact_changes = 0;
      // Wall time of the elements' part (s), without the contact search.
      double element_time = 0.;
    };

    class SheetModel
    {
    public:
      // Reads subsection Contact (tool files relative to input_directory)
      // and the stages' tool settings, checks the parameters across
      // subsections (ModelParameters::check), and sets up the first stage
      // on the blank's mesh. Throws InputError; writes nothing.
      SheetModel(ParameterHandler      &prm,
                 const ModelParameters &parameters,
                 const std::string     &input_directory);

      // The initial state's contact with the tools: a tool inside the blank
      // or turned away from it is an input error (D56), found before
      // anything is written. Returns the number of sheet nodes that start
      // inside a tool (by less than half the thickness).
      unsigned int
      place_tools();
      // The Newton system of the current mesh and stage: the contact pairs
      // of the tools that take part, the constraints, the linear system,
      // the thickness measurement.
      void
      set_up_system();
      // Stage `index` begins (D101): the tools and constraints of the
      // stage, the contact state carried over, a new stage's first
      // increment from the tangent predictor. Throws InputError if a tool
      // that comes in starts inside the sheet.
      void
      begin_stage(unsigned int index);
      const process::Stage &
      stage() const;
      // The stage ends: the force scale the next stage begins with (D102),
      // before a force release the forces it releases (D150); a tool
      // retraction must have opened every pair. Returns "" or why the run
      // cannot go on.
      std::string
      end_stage();
      // A force release's loads at load t: the released forces times
      // (t_end - t) / (t_end - t_start) (sheet_model_release.cc).
      double
      release_factor(double load) const;

      // The prescribed increments and tool positions of [old_load,
      // new_load].
      void
      prepare_increment(double old_load, double new_load);
      // The trial element-internal unknowns: the committed ones times
      // ratio.
      void
      start_enhanced_parameters(double ratio);
      // Residual (rhs = -r on free dofs), internal forces and, with
      // with_matrix, tangent at the unknowns, through the constraints; the
      // trial history from du. predictor: the increment's predictor solve.
      AssemblyResult
      assemble(const Vector<double>            &unknowns,
               const AffineConstraints<double> &constraints_used,
               bool                             with_matrix,
               double                           load,
               bool                             predictor);
      // The converged unknowns of the increment [start_load, end_load]
      // become the committed state; the mesh moves by their du.
      void
      commit(Vector<double> &unknowns, double start_load, double end_load);
      // A re-equilibration's result (no load step): the history, the
      // contact forces and tool positions; the mesh moves by du.
      void
      commit_equilibrium(Vector<double> &unknowns);
      // The trial state back to the committed one (a failed attempt).
      void
      restore_trial_state();
      // Solves the last assembly's system for a Newton correction (throws
      // if the solve fails), leaving out the rows that hold only their
      // diagonal where Linear solver asks it (D60).
      void
      solve(Vector<double> &correction);

      // Refines the cells the adaptation flagged, carries the committed
      // state over with the contact pairs (D83) and sets the system up.
      void
      refine(const adaptivity::MeshAdaptation &adaptation);
      // The checkpoint's state (its stage set up first, an adaptive run's
      // refinements replayed, D84); throws InputError if it does not
      // belong to this model.
      void
      restore(state::SimulationState &&saved);

      const ModelParameters &
      model_parameters() const;
      const material::ElastoPlasticity &
      material() const;
      discretisation::SheetDiscretisation &
      sheet();
      const discretisation::SheetDiscretisation &
      sheet() const;
      const discretisation::ThicknessMeasurement &
      thickness() const;
      const discretisation::NewtonConstraints &
      constraints() const;
      contact::ContactCoupling &
      contact();
      const contact::ContactCoupling &
      contact() const;
      linear_algebra::NewtonLinearSystem &
      linear_system();
      const linear_algebra::NewtonLinearSystem &
      linear_system() const;
      // The committed state; its history and enhanced parameters are those
      // of the cells this rank evaluates (sheet().owned_cells(), D217).
      state::SimulationState &
      state();
      const state::SimulationState &
      state() const;
      // The committed state with every cell's history and enhanced
      // parameters, on rank 0 (a checkpoint); every rank must call it, and
      // the other ranks' copies hold no cell records.
      state::SimulationState
      whole_state();
      // Internal nodal forces of the last assembly.
      const Vector<double> &
      internal_force() const;
      // The force scale of the last assembly (doc/theory.md §5.2): the
      // larger of ||f_int|| over the displacement dofs and the largest tool
      // force, at least the stage's (D102).
      double
      force_scale() const;
      // The faces with a prescribed displacement in some stage.
      const std::vector<unsigned int> &
      reaction_faces() const;
      // All Newton unknowns: displacements, contact forces, tool positions.
      types::global_dof_index
      n_unknowns() const;

    private:
      // Release stages (sheet_model_release.cc, D150, D151). Input time:
      // every release stage's symmetry planes, prescribed faces and
      // supports (at their points) stop the six rigid-body modes; throws
      // InputError naming Release supports.
      void
      check_release_supports() const;
      // At a release stage's start: the node of each support, nearest to
      // its point where the sheet stands, and the six modes stopped by the
      // nodes found (InputError if not: the stage cannot begin).
      void
      find_release_supports();
      // The displacement dofs the supports hold (none outside a release).
      std::vector<types::global_dof_index>
      held_dofs() const;
      // rhs += the release loads at `load` on the rows the constraints
      // leave free.
      void
      add_release_loads(const AffineConstraints<double> &constraints,
                        double                           load,
                        Vector<double>                  &rhs) const;

      // The initial state on the blank's mesh.
      void
      initialize_state();
      // Adds du to the total displacement and moves the mesh by it
      // (updated Lagrangian).
      void
      move_mesh(Vector<double> &unknowns);
      // Whether the element keeps enhanced parameters per cell
      // (incompatible modes).
      bool
      has_enhanced_parameters() const;
      // Each rank's own cells' records of a whole cell state.
      void
      keep_own_cell_state(state::SimulationState &whole) const;
      // The Newton solutions of the committed state sized for the current
      // unknowns: their displacement blocks kept, the contact blocks from
      // the pairs before the change (parents: of a refinement, none: of a
      // stage; contact::ContactCoupling::transfer).
      void
      carry_contact_state(const contact::ContactCoupling::Snapshot &old,
                          const std::vector<fe::VertexParents>     &parents,
                          const std::vector<double>                &old_area);

      const ModelParameters                              &parameters;
      std::unique_ptr<material::ElastoPlasticity>         material_model;
      discretisation::SheetDiscretisation                 discretisation;
      std::unique_ptr<fe::HexahedronElement>              element;
      discretisation::ThicknessMeasurement                thickness_measurement;
      discretisation::NewtonConstraints                   newton_constraints;
      contact::ContactCoupling                            contact_coupling;
      std::unique_ptr<linear_algebra::NewtonLinearSystem> system;
      std::vector<unsigned int>                           faces_with_reactions;
      ViscousStabilization                                viscous_stabilization;
      // Committed when an increment converges; the trial values of the
      // increment being solved are restored from it on a cut-back.
      state::SimulationState                  committed;
      std::vector<fe::QuadraturePointHistory> trial_history;
      std::vector<fe::EnhancedParameters>     trial_enhanced_parameters;
      Vector<double>                          internal_forces;
    };
  } // namespace problem
} // namespace deepdraw

#endif
