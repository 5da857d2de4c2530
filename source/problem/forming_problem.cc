// Set-up of FormingProblem: the model for the first stage, the Newton
// system of a mesh and a stage, the transition from one stage to the next
// and the commit of a converged increment. The loop is in
// forming_problem_run.cc, one increment in forming_problem_newton.cc.
#include <algorithm>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/problem/forming_problem.h>

namespace deepdraw
{
  namespace problem
  {
    void
    FormingProblem::declare_parameters(ParameterHandler &prm)
    {
      ModelParameters::declare_parameters(prm);
    }


    FormingProblem::FormingProblem(ParameterHandler  &prm,
                                   const std::string &input_directory)
    {
      parameters.parse_parameters(prm, input_directory);
      contact_coupling.parse_parameters(prm, input_directory);
      contact_coupling.parse_stages(parameters.stages);
      postprocessors.parse_parameters(prm);
      parameters.check(contact_coupling);
      adaptation
        = std::make_unique<adaptivity::MeshAdaptation>(parameters.adaptivity);

      material_model
        = std::make_unique<material::HillPlasticity>(parameters.material);
      linear_system
        = linear_algebra::make_serial_system(parameters.linear_solver);
      discretisation.create(parameters.geometry);
      element = std::make_unique<fe::HexahedronElement>(
        parameters.element,
        *material_model,
        discretisation.dof_handler().get_fe());
      if (contact_coupling.active())
        contact_coupling.create_tools(parameters.square_cup_tools,
                                      parameters.geometry.thickness,
                                      parameters.geometry.symmetry_plane_x,
                                      parameters.geometry.symmetry_plane_y);
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


    void
    FormingProblem::set_up_system()
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
                                           discretisation.blank_element_size());
      linear_algebra::SystemLayout layout;
      layout.multiplier_blocks = contact_coupling.multiplier_blocks();
      constraints.set_up(discretisation,
                         stage().prescribed,
                         layout.multiplier_blocks,
                         n);
      layout.dof_handler           = &discretisation.dof_handler();
      layout.constraints           = &constraints.homogeneous();
      layout.n_unknowns            = n;
      layout.add_contact_couplings = [this](DynamicSparsityPattern &dsp)
      { contact_coupling.add_sparsity(dsp); };
      layout.tool_positions = contact_coupling.tool_position_unknowns();
      linear_system->reinit(layout);
      internal_forces.reinit(n);
      newton_unknowns.reinit(n);
      thickness_measurement.set_up(discretisation.triangulation(),
                                   discretisation.initial_vertices());
      thickness_measurement.update(discretisation.triangulation(),
                                   parameters.geometry.thickness);
      postprocessors.initialize(*this);
    }


    void
    FormingProblem::initialize_state()
    {
      committed.total_displacement.reinit(discretisation.n_displacement_dofs());
      committed.converged_solution.reinit(newton_unknowns.size());
      // Unstressed, material axes rotated about z by Material/Rolling
      // direction angle.
      fe::QuadraturePointHistory initial_point;
      initial_point.material_axes = parameters.material.initial_material_axes();
      const unsigned int n_cells
        = discretisation.triangulation().n_active_cells();
      committed.history.assign(n_cells * fe::n_weighted_points, initial_point);
      committed.vertices = discretisation.triangulation().get_vertices();
      committed.enhanced_parameters.assign(
        fe::n_enhanced_parameters(parameters.element.technology) > 0 ? n_cells
                                                                     : 0,
        fe::EnhancedParameters());
      trial_history             = committed.history;
      trial_enhanced_parameters = committed.enhanced_parameters;
      committed.next_increment
        = std::min(stage().load_stepping.initial_increment,
                   stage().load_stepping.maximum_increment);
    }


    const process::Stage &
    FormingProblem::stage() const
    {
      return parameters.stages[committed.stage];
    }


    void
    FormingProblem::begin_stage(const unsigned int index)
    {
      // The pairs of the tools that stay keep their state and forces, the
      // tools that leave take theirs with them, those that come start open
      // (D101).
      contact::ContactCoupling::Snapshot snapshot;
      if (contact_coupling.active())
        snapshot
          = contact_coupling.snapshot(committed.converged_solution,
                                      committed.previous_converged_solution);
      std::vector<bool> new_tools(contact_coupling.tools().size(), false);
      for (unsigned int k = 0; k < new_tools.size(); ++k)
        new_tools[k] = !contact_coupling.takes_part(k);
      committed.stage           = index;
      committed.stage_completed = false;
      contact_coupling.begin_stage(index);
      set_up_system();
      const types::global_dof_index n_u = discretisation.n_displacement_dofs();
      Vector<double>                converged(newton_unknowns.size());
      for (types::global_dof_index i = 0; i < n_u; ++i)
        converged[i] = committed.converged_solution[i];
      Vector<double> before(newton_unknowns.size());
      for (types::global_dof_index i = 0; i < n_u; ++i)
        before[i] = committed.previous_converged_solution[i];
      if (contact_coupling.active())
      {
        contact_coupling.transfer(snapshot, {}, {}, {}, converged, before);
        committed.contact = contact_coupling.committed_history();
      }
      committed.converged_solution          = converged;
      committed.previous_converged_solution = before;
      // A new stage starts from the tangent predictor: the last increment
      // of another stage says nothing about the first of this one.
      committed.last_load_increment = 0.;
      committed.next_increment
        = std::min(stage().load_stepping.initial_increment,
                   stage().load_stepping.maximum_increment);
      newton_unknowns = committed.converged_solution;

      // A tool that comes in must not start inside the sheet (D56).
      for (unsigned int k = 0; k < new_tools.size(); ++k)
        new_tools[k] = new_tools[k] && contact_coupling.takes_part(k);
      if (std::count(new_tools.begin(), new_tools.end(), true) > 0)
      {
        contact_coupling.start_increment(committed.load, committed.load);
        assemble(newton_unknowns, constraints.homogeneous(), false);
        try
        {
          contact_coupling.check_initial_placement(
            discretisation.triangulation().get_vertices(),
            parameters.geometry.thickness,
            committed.load,
            new_tools);
        }
        catch (const InputError &error)
        {
          stop_cleanly("stage " + std::to_string(index + 1) + " '"
                       + stage().name + "' cannot begin: " + error.what());
        }
      }
    }


    void
    FormingProblem::commit_increment()
    {
      committed.history             = trial_history;
      committed.enhanced_parameters = trial_enhanced_parameters;
      discretisation.hanging_node_constraints().distribute(newton_unknowns);
      committed.previous_converged_solution = committed.converged_solution;
      committed.converged_solution          = newton_unknowns;
      committed.last_load_increment         = target_load - start_load;
      committed.load                        = target_load;
      if (contact_coupling.active())
      {
        contact_coupling.commit(newton_unknowns);
        committed.contact = contact_coupling.committed_history();
      }
      move_mesh();
    }


    void
    FormingProblem::move_mesh()
    {
      // Hanging dofs follow their masters (the predictor's damped step can
      // leave them behind).
      discretisation.hanging_node_constraints().distribute(newton_unknowns);
      for (types::global_dof_index i = 0;
           i < discretisation.n_displacement_dofs();
           ++i)
        committed.total_displacement[i] += newton_unknowns[i];
      discretisation.move_vertices(newton_unknowns);
      committed.vertices = discretisation.triangulation().get_vertices();
      thickness_measurement.update(discretisation.triangulation(),
                                   parameters.geometry.thickness);
    }
  } // namespace problem
} // namespace deepdraw
