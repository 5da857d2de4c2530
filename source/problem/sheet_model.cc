// SheetModel: the set-up of the first stage, the transitions between stages,
// the commit of converged increments, refinement and restart.
#include <algorithm>
#include <cmath>
#include <deepdraw/blank/nodal_surface_area.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/parallel/cell_partition.h>
#include <deepdraw/problem/sheet_model.h>

namespace deepdraw
{
  namespace problem
  {
    SheetModel::SheetModel(ParameterHandler      &prm,
                           const ModelParameters &parameters,
                           const std::string     &input_directory)
        : parameters(parameters)
    {
      contact_coupling.parse_parameters(prm, input_directory);
      contact_coupling.parse_stages(parameters.stages);
      parameters.check(contact_coupling);

      material_model
        = std::make_unique<material::ElastoPlasticity>(parameters.material);
      system = linear_algebra::make_system(parameters.linear_solver);
      discretisation.create(parameters.geometry,
                            parameters.element.points_through_thickness);
      element = std::make_unique<fe::HexahedronElement>(
        parameters.element,
        *material_model,
        discretisation.dof_handler().get_fe());
      if (contact_coupling.active())
        contact_coupling.create_tools(parameters.square_cup_tools,
                                      parameters.geometry.thickness,
                                      parameters.geometry.symmetry_plane_x,
                                      parameters.geometry.symmetry_plane_y);
      check_release_supports();
      for (const process::Stage &stage : parameters.stages)
        for (const process::PrescribedDisplacement &entry :
             stage.prescribed.entries)
          faces_with_reactions.push_back(entry.boundary_id);
      std::sort(faces_with_reactions.begin(), faces_with_reactions.end());
      faces_with_reactions.erase(std::unique(faces_with_reactions.begin(),
                                             faces_with_reactions.end()),
                                 faces_with_reactions.end());
      set_up_system();
      initialize_state();
    }


    unsigned int
    SheetModel::place_tools()
    {
      if (!contact_coupling.active())
        return 0;
      contact_coupling.start_increment(0., 0.);
      Vector<double> unknowns(n_unknowns());
      assemble(unknowns, newton_constraints.homogeneous(), false, 0., false);
      const auto &vertices = discretisation.triangulation().get_vertices();
      contact_coupling.check_initial_placement(vertices,
                                               parameters.geometry.thickness);
      contact_coupling.commit(unknowns);
      committed.contact = contact_coupling.committed_history();
      return contact_coupling.n_initial_penetrations(vertices);
    }


    void
    SheetModel::set_up_system()
    {
      const types::global_dof_index n_u = discretisation.n_displacement_dofs();
      types::global_dof_index       n   = n_u;
      // The augmentation keeps the element size of the blank's mesh on
      // refined meshes: it changes the iterates, not the converged
      // solution (D82).
      if (contact_coupling.active())
        n += contact_coupling.create_pairs(discretisation.face_vertices(),
                                           discretisation.vertex_dofs(),
                                           n_u,
                                           parameters.material.youngs_modulus,
                                           discretisation.blank_element_size(),
                                           parallel::n_ranks() > 1
                                             ? parallel::vertex_owners(
                                               discretisation.triangulation())
                                             : std::vector<unsigned int>());
      linear_algebra::SystemLayout layout;
      layout.multiplier_blocks = contact_coupling.multiplier_blocks();
      newton_constraints.set_up(discretisation,
                                stage().prescribed,
                                layout.multiplier_blocks,
                                n,
                                held_dofs());
      layout.dof_handler           = &discretisation.dof_handler();
      layout.constraints           = &newton_constraints.homogeneous();
      layout.n_unknowns            = n;
      layout.add_contact_couplings = [this](DynamicSparsityPattern &dsp)
      { contact_coupling.add_sparsity(dsp); };
      layout.tool_positions = contact_coupling.tool_position_unknowns();
      system->reinit(layout);
      internal_forces.reinit(n);
      thickness_measurement.set_up(discretisation.triangulation(),
                                   discretisation.initial_vertices());
      thickness_measurement.update(discretisation.triangulation(),
                                   parameters.geometry.thickness);
    }


    void
    SheetModel::initialize_state()
    {
      committed.total_displacement.reinit(discretisation.n_displacement_dofs());
      committed.converged_solution.reinit(n_unknowns());
      // Unstressed, material axes rotated about z by Material/Rolling
      // direction angle.
      fe::QuadraturePointHistory initial_point;
      initial_point.material_axes = parameters.material.initial_material_axes();
      // Each rank the state of its own cells (D217).
      const unsigned int n_cells = discretisation.owned_cells().n_owned();
      committed.history.assign(n_cells * discretisation.n_points_per_cell(),
                               initial_point);
      committed.vertices = discretisation.triangulation().get_vertices();
      committed.enhanced_parameters.assign(has_enhanced_parameters() ? n_cells
                                                                     : 0,
                                           fe::EnhancedParameters());
      committed.next_increment
        = std::min(stage().load_stepping.initial_increment,
                   stage().load_stepping.maximum_increment);
      restore_trial_state();
    }


    const process::Stage &
    SheetModel::stage() const
    {
      return parameters.stages[committed.stage];
    }


    void
    SheetModel::begin_stage(const unsigned int index)
    {
      // The pairs of the tools that stay keep their state and forces, the
      // tools that leave take theirs with them, those that come start open
      // (D101).
      contact::ContactCoupling::Snapshot snapshot;
      if (contact_coupling.active())
        snapshot
          = contact_coupling.snapshot(committed.converged_solution,
                                      committed.previous_converged_solution);
      std::vector<bool> new_tools(contact_coupling.tools().size());
      for (unsigned int k = 0; k < new_tools.size(); ++k)
        new_tools[k] = !contact_coupling.takes_part(k);
      // A stage that releases what the last one carried converges against
      // the forces it releases, not against the forces that are left
      // (D102); as the last stage ended, also after a resume.
      committed.stage_force_scale = committed.end_force_scale >= 0.
                                      ? committed.end_force_scale
                                      : force_scale();
      committed.stage             = index;
      committed.stage_completed   = false;
      committed.end_force_scale   = -1.;
      contact_coupling.begin_stage(index);
      find_release_supports();
      set_up_system();
      carry_contact_state(snapshot, {}, {});
      // A force along a component the stage prescribes is the constraint's
      // now.
      newton_constraints.clear_constrained_multipliers(
        committed.converged_solution);
      newton_constraints.clear_constrained_multipliers(
        committed.previous_converged_solution);
      // A new stage starts from the tangent predictor: the last increment
      // of another stage says nothing about the first of this one.
      committed.last_load_increment = 0.;
      committed.next_increment
        = std::min(stage().load_stepping.initial_increment,
                   stage().load_stepping.maximum_increment);

      // A tool that comes in must not start inside the sheet (D56).
      for (unsigned int k = 0; k < new_tools.size(); ++k)
        new_tools[k] = new_tools[k] && contact_coupling.takes_part(k);
      if (std::count(new_tools.begin(), new_tools.end(), true) == 0)
        return;
      // The contact state where the sheet stands (du = 0).
      Vector<double> unknowns = committed.converged_solution;
      for (types::global_dof_index i = 0;
           i < discretisation.n_displacement_dofs();
           ++i)
        unknowns[i] = 0.;
      contact_coupling.start_increment(committed.load, committed.load);
      assemble(unknowns,
               newton_constraints.homogeneous(),
               false,
               committed.load,
               false);
      restore_trial_state();
      contact_coupling.check_initial_placement(
        discretisation.triangulation().get_vertices(),
        parameters.geometry.thickness,
        committed.load,
        new_tools);
    }


    void
    SheetModel::carry_contact_state(
      const contact::ContactCoupling::Snapshot &old,
      const std::vector<fe::VertexParents>     &parents,
      const std::vector<double>                &old_area)
    {
      const types::global_dof_index n_u = discretisation.n_displacement_dofs();
      std::array<Vector<double> *, 2> solutions
        = {{&committed.converged_solution,
            &committed.previous_converged_solution}};
      std::array<Vector<double>, 2> extended;
      for (unsigned int s = 0; s < 2; ++s)
      {
        extended[s].reinit(n_unknowns());
        for (types::global_dof_index i = 0; i < n_u; ++i)
          extended[s][i] = (*solutions[s])[i];
      }
      if (contact_coupling.active())
      {
        contact_coupling.transfer(old,
                                  parents,
                                  old_area,
                                  parents.empty()
                                    ? std::vector<double>()
                                    : blank::nodal_surface_area(
                                      discretisation.triangulation()),
                                  extended[0],
                                  extended[1]);
        committed.contact = contact_coupling.committed_history();
      }
      committed.converged_solution          = std::move(extended[0]);
      committed.previous_converged_solution = std::move(extended[1]);
    }


    void
    SheetModel::commit(Vector<double> &unknowns,
                       const double    start_load,
                       const double    end_load)
    {
      committed.history             = trial_history;
      committed.enhanced_parameters = trial_enhanced_parameters;
      discretisation.hanging_node_constraints().distribute(unknowns);
      committed.previous_converged_solution = committed.converged_solution;
      committed.converged_solution          = unknowns;
      committed.last_load_increment         = end_load - start_load;
      committed.load                        = end_load;
      if (contact_coupling.active())
      {
        contact_coupling.commit(unknowns);
        committed.contact = contact_coupling.committed_history();
      }
      move_mesh(unknowns);
    }


    void
    SheetModel::commit_equilibrium(Vector<double> &unknowns)
    {
      // The Newton solution keeps the last increment's du (the
      // extrapolation predictor scales it) with the re-equilibrated
      // multipliers and tool positions.
      committed.history = trial_history;
      for (types::global_dof_index i = discretisation.n_displacement_dofs();
           i < unknowns.size();
           ++i)
        committed.converged_solution[i] = unknowns[i];
      if (contact_coupling.active())
      {
        contact_coupling.commit(unknowns);
        committed.contact = contact_coupling.committed_history();
      }
      move_mesh(unknowns);
    }


    void
    SheetModel::move_mesh(Vector<double> &unknowns)
    {
      // Hanging dofs follow their masters (the predictor's damped step can
      // leave them behind).
      discretisation.hanging_node_constraints().distribute(unknowns);
      for (types::global_dof_index i = 0;
           i < discretisation.n_displacement_dofs();
           ++i)
        committed.total_displacement[i] += unknowns[i];
      discretisation.move_vertices(unknowns);
      committed.vertices = discretisation.triangulation().get_vertices();
      thickness_measurement.update(discretisation.triangulation(),
                                   parameters.geometry.thickness);
    }


    bool
    SheetModel::has_enhanced_parameters() const
    {
      return fe::n_enhanced_parameters(
               parameters.element.technology,
               parameters.element.points_through_thickness)
             > 0;
    }


    void
    SheetModel::keep_own_cell_state(state::SimulationState &whole) const
    {
      const parallel::OwnedCells &cells = discretisation.owned_cells();
      whole.history = cells.keep_own(std::move(whole.history),
                                     discretisation.n_points_per_cell());
      whole.enhanced_parameters
        = cells.keep_own(std::move(whole.enhanced_parameters),
                         has_enhanced_parameters() ? 1 : 0);
    }


    state::SimulationState
    SheetModel::whole_state()
    {
      // The cell records are set aside while the rest is copied, and put
      // back also if the copy fails: gathered below, they are not copied
      // twice (D221).
      state::SimulationState whole;
      {
        std::vector<fe::QuadraturePointHistory> history
          = std::move(committed.history);
        std::vector<fe::EnhancedParameters> enhanced
          = std::move(committed.enhanced_parameters);
        const auto put_back = [&]()
        {
          committed.history             = std::move(history);
          committed.enhanced_parameters = std::move(enhanced);
        };
        try
        {
          whole = committed;
        }
        catch (...)
        {
          put_back();
          throw;
        }
        put_back();
      }
      const parallel::OwnedCells &cells = discretisation.owned_cells();
      whole.history = cells.gather_on_root(committed.history,
                                           discretisation.n_points_per_cell());
      whole.enhanced_parameters
        = cells.gather_on_root(committed.enhanced_parameters,
                               has_enhanced_parameters() ? 1 : 0);
      return whole;
    }


    void
    SheetModel::restore_trial_state()
    {
      trial_history             = committed.history;
      trial_enhanced_parameters = committed.enhanced_parameters;
    }


    void
    SheetModel::refine(const adaptivity::MeshAdaptation &adaptation)
    {
      contact::ContactCoupling::Snapshot snapshot;
      std::vector<double>                old_area;
      if (contact_coupling.active())
      {
        snapshot
          = contact_coupling.snapshot(committed.converged_solution,
                                      committed.previous_converged_solution);
        old_area = blank::nodal_surface_area(discretisation.triangulation());
      }
      const std::vector<fe::VertexParents> parents
        = adaptation.refine(discretisation,
                            committed,
                            *material_model,
                            has_enhanced_parameters());
      set_up_system();
      // The transfer kept the displacement blocks of the Newton solutions;
      // the contact blocks are those of the new pairs, started from the
      // pairs at the parents of their nodes (D83).
      carry_contact_state(snapshot, parents, old_area);
      restore_trial_state();
    }


    namespace
    {
      // The checkpointed state must belong to this mesh and contact set-up.
      void
      check_size(const std::string &what,
                 const std::size_t  checkpointed,
                 const std::size_t  expected)
      {
        if (checkpointed != expected)
          throw InputError("--resume: the checkpoint has "
                           + std::to_string(checkpointed) + " " + what
                           + ", this model " + std::to_string(expected));
      }
    } // namespace


    void
    SheetModel::restore(state::SimulationState &&saved)
    {
      // The mesh is rebuilt from the prm; an adaptive run's refinements
      // are replayed on it (D84), and the stage's tools and constraints
      // set up.
      if (!saved.refinements.empty())
        discretisation.replay_refinements(saved.refinements);
      committed.stage                    = saved.stage;
      committed.release_support_vertices = saved.release_support_vertices;
      contact_coupling.begin_stage(saved.stage);
      set_up_system();
      check_size("vertices",
                 saved.vertices.size(),
                 discretisation.triangulation().n_vertices());
      check_size("displacement unknowns",
                 saved.total_displacement.size(),
                 discretisation.n_displacement_dofs());
      check_size("Newton unknowns",
                 saved.converged_solution.size(),
                 n_unknowns());
      // Against the mesh (the refinements replayed), not the initial state.
      const std::size_t n_cells
        = discretisation.triangulation().n_active_cells();
      check_size("quadrature points (Finite element/Points through the "
                 "thickness)",
                 saved.history.size(),
                 n_cells * discretisation.n_points_per_cell());
      check_size("cells with enhanced parameters",
                 saved.enhanced_parameters.size(),
                 has_enhanced_parameters() ? n_cells : 0);
      if (contact_coupling.active())
        contact_coupling.restore(saved.contact);
      committed = std::move(saved);
      keep_own_cell_state(committed);
      // The configuration x_t of the checkpoint (updated Lagrangian).
      discretisation.set_vertices(committed.vertices);
      thickness_measurement.update(discretisation.triangulation(),
                                   parameters.geometry.thickness);
      restore_trial_state();
    }


    const ModelParameters &
    SheetModel::model_parameters() const
    {
      return parameters;
    }


    const material::ElastoPlasticity &
    SheetModel::material() const
    {
      return *material_model;
    }


    discretisation::SheetDiscretisation &
    SheetModel::sheet()
    {
      return discretisation;
    }


    const discretisation::SheetDiscretisation &
    SheetModel::sheet() const
    {
      return discretisation;
    }


    const discretisation::ThicknessMeasurement &
    SheetModel::thickness() const
    {
      return thickness_measurement;
    }


    const discretisation::NewtonConstraints &
    SheetModel::constraints() const
    {
      return newton_constraints;
    }


    contact::ContactCoupling &
    SheetModel::contact()
    {
      return contact_coupling;
    }


    const contact::ContactCoupling &
    SheetModel::contact() const
    {
      return contact_coupling;
    }


    linear_algebra::NewtonLinearSystem &
    SheetModel::linear_system()
    {
      return *system;
    }


    const linear_algebra::NewtonLinearSystem &
    SheetModel::linear_system() const
    {
      return *system;
    }


    state::SimulationState &
    SheetModel::state()
    {
      return committed;
    }


    const state::SimulationState &
    SheetModel::state() const
    {
      return committed;
    }


    const Vector<double> &
    SheetModel::internal_force() const
    {
      return internal_forces;
    }


    const std::vector<unsigned int> &
    SheetModel::reaction_faces() const
    {
      return faces_with_reactions;
    }


    double
    SheetModel::force_scale() const
    {
      double sum = 0.;
      for (types::global_dof_index i = 0;
           i < discretisation.n_displacement_dofs();
           ++i)
        sum += internal_forces[i] * internal_forces[i];
      double scale = std::sqrt(sum);
      for (const Tensor<1, 3> &force : contact_coupling.tool_forces())
        scale = std::max(scale, force.norm());
      return std::max(scale, committed.stage_force_scale);
    }


    types::global_dof_index
    SheetModel::n_unknowns() const
    {
      return internal_forces.size();
    }
  } // namespace problem
} // namespace deepdraw
