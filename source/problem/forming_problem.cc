// Parameters, set-up and the increment loop of FormingProblem; one
// increment's Newton iterations in forming_problem_newton.cc, the assembly in
// forming_problem_assembly.cc, the output in forming_problem_output.cc.
#include <algorithm>
#include <cmath>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deepdraw/fe/hanging_node_constraints.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/problem/forming_problem.h>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>

namespace deepdraw
{
  namespace problem
  {
    void
    FormingProblem::declare_parameters(ParameterHandler &prm)
    {
      BlankGeometry::declare_parameters(prm);
      ProcessParameters::declare_parameters(prm);
      ProcessTables::declare_parameters(prm);
      prm.enter_subsection("Material");
      material::MaterialParameters::declare_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Finite element");
      fe::ElementParameters::declare_parameters(prm);
      prm.leave_subsection();
      PrescribedDisplacements::declare_parameters(prm);
      solver::IncrementControlParameters::declare_parameters(prm);
      solver::NewtonParameters::declare_parameters(prm);
      solver::LinearSolverParameters::declare_parameters(prm);
      io::OutputParameters::declare_parameters(prm);
      geometry::SquareCupToolParameters::declare_parameters(prm);
      ContactCoupling::declare_parameters(prm);
      CheckpointParameters::declare_parameters(prm);
      AdaptivityParameters::declare_parameters(prm);
    }


    FormingProblem::FormingProblem(ParameterHandler  &prm,
                                   const std::string &input_directory)
        : fe(FE_Q<3>(1), 3)
        , dof_handler(triangulation)
        , fe_scalar(1)
        , scalar_dof_handler(triangulation)
    {
      geometry.parse_parameters(prm, input_directory);
      process_parameters.parse_parameters(prm);
      process_tables.parse_parameters(prm, geometry);
      prm.enter_subsection("Material");
      material_parameters.parse_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Finite element");
      element_parameters.parse_parameters(prm);
      prm.leave_subsection();
      prescribed.parse_parameters(prm,
                                  geometry.symmetry_plane_x,
                                  geometry.symmetry_plane_y);
      increment_parameters.parse_parameters(prm);
      increment_parameters.final_load = process_parameters.final_load;
      newton_parameters.parse_parameters(prm);
      linear_solver_parameters.parse_parameters(prm);
      output_parameters.parse_parameters(prm);
      square_cup_tool_parameters.parse_parameters(prm);
      contact.parse_parameters(prm,
                               input_directory,
                               process_parameters.blank_holder_force);
      checkpoint_parameters.parse_parameters(prm);
      adaptivity_parameters.parse_parameters(prm);
      parameter_listing = flatten_parameters(prm);
      check_input();

      // Thickness profiles are square-cup tables: runs with tools only.
      if (contact.active())
        for (const double travel : output_parameters.thickness_profile_travels)
          if (travel <= process_parameters.final_load * (1. + 1e-12))
            profile_travels.push_back(travel);
      std::sort(profile_travels.begin(), profile_travels.end());
      profile_travels.erase(std::unique(profile_travels.begin(),
                                        profile_travels.end()),
                            profile_travels.end());

      material
        = std::make_unique<material::ElastoPlasticity>(material_parameters);
      element = std::make_unique<fe::HexahedronElement>(element_parameters,
                                                        *material,
                                                        fe);
      linear_solver
        = std::make_unique<solver::LinearSolver>(linear_solver_parameters);
      setup_system();
      process_tables.set_up(contact,
                            process_parameters.final_load,
                            *sheet_thickness,
                            initial_vertices);
    }


    void
    FormingProblem::setup_system()
    {
      geometry.create_mesh(triangulation);
      initial_vertices = triangulation.get_vertices();
      // The mean in-plane element size of the blank (for the rectangle as
      // before, to the bit); the contact augmentation keeps it on refined
      // meshes (D82).
      blank_element_size
        = geometry.outline == BlankGeometry::Outline::rectangle
            ? std::sqrt(geometry.length / geometry.elements_along_x
                        * geometry.width / geometry.elements_along_y)
            : std::sqrt(GridTools::volume(triangulation) / geometry.thickness
                        / geometry.n_plane_cells());
      if (contact.active())
        contact.create_tools(square_cup_tool_parameters,
                             geometry.thickness,
                             geometry.symmetry_plane_x,
                             geometry.symmetry_plane_y);
      dof_handler.distribute_dofs(fe);
      setup_dofs();
      state.total_displacement.reinit(dof_handler.n_dofs());
      state.converged_solution.reinit(newton_unknowns.size());

      // Initial state: unstressed, material axes rotated about z by
      // Material/Rolling direction angle.
      QuadraturePointHistory initial_point;
      initial_point.material_axes = material_parameters.initial_material_axes();
      state.history.assign(triangulation.n_active_cells()
                             * fe::n_weighted_points,
                           initial_point);
      trial_history  = state.history;
      state.vertices = triangulation.get_vertices();
      state.enhanced_parameters.assign(
        fe::n_enhanced_parameters(element_parameters.technology) > 0
          ? triangulation.n_active_cells()
          : 0,
        fe::EnhancedParameters());
      trial_enhanced_parameters = state.enhanced_parameters;

      reaction_faces.clear();
      for (const PrescribedDisplacement &entry : prescribed.entries)
        if (std::find(reaction_faces.begin(),
                      reaction_faces.end(),
                      entry.boundary_id)
            == reaction_faces.end())
          reaction_faces.push_back(entry.boundary_id);
      std::sort(reaction_faces.begin(), reaction_faces.end());

      update_cell_geometry();
      compute_thickness();
    }


    void
    FormingProblem::setup_dofs()
    {
      // Hanging vertices of a refined mesh (doc/theory.md §8): their dofs
      // follow their masters, so they are neither prescribed nor contact
      // nodes (D82).
      hanging_node_constraints.clear();
      fe::make_q1_hanging_node_constraints(dof_handler,
                                           hanging_node_constraints);
      hanging_node_constraints.close();
      scalar_dof_handler.distribute_dofs(fe_scalar);

      vertex_dofs.assign(triangulation.n_vertices(),
                         {{numbers::invalid_dof_index,
                           numbers::invalid_dof_index,
                           numbers::invalid_dof_index}});
      dof_initial_position.resize(dof_handler.n_dofs());
      dof_component.resize(dof_handler.n_dofs());
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int c = 0; c < 3; ++c)
          {
            const auto dof = cell->vertex_dof_index(v, c);
            vertex_dofs[cell->vertex_index(v)][c] = dof;
            dof_initial_position[dof] = initial_vertices[cell->vertex_index(v)];
            dof_component[dof]        = c;
          }

      // Vertices of each face of the blank (by boundary id), sorted.
      std::vector<std::vector<unsigned int>> face_vertices(6);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            for (const unsigned int v : face->vertex_indices())
              face_vertices[face->boundary_id()].push_back(
                face->vertex_index(v));
      for (unsigned int id = 0; id < face_vertices.size(); ++id)
      {
        auto &vertices = face_vertices[id];
        std::sort(vertices.begin(), vertices.end());
        vertices.erase(std::unique(vertices.begin(), vertices.end()),
                       vertices.end());
        face_dofs[id].clear();
        for (const unsigned int vertex : vertices)
          face_dofs[id].insert(face_dofs[id].end(),
                               vertex_dofs[vertex].begin(),
                               vertex_dofs[vertex].end());
        std::sort(face_dofs[id].begin(), face_dofs[id].end());
      }

      // The faces' reactions sum over all their vertices; prescribed dofs
      // and contact pairs are those of the vertices that are not hanging.
      for (auto &vertices : face_vertices)
        vertices.erase(
          std::remove_if(vertices.begin(),
                         vertices.end(),
                         [&](const unsigned int vertex) {
                           return hanging_node_constraints.is_constrained(
                             vertex_dofs[vertex][0]);
                         }),
          vertices.end());

      // Prescribed dofs; a later entry overrides an earlier one.
      std::map<types::global_dof_index, const PrescribedDisplacement *> owner;
      for (const PrescribedDisplacement &entry : prescribed.entries)
        for (const unsigned int vertex : face_vertices[entry.boundary_id])
          owner[vertex_dofs[vertex][entry.component]] = &entry;
      prescribed_dofs.assign(owner.begin(), owner.end());

      // Contact unknowns follow the displacements (block system of
      // reference Eq. 19). The augmentation keeps the element size of the
      // blank's mesh on refined meshes: it changes the iterates, not the
      // converged solution (D82).
      types::global_dof_index n_unknowns = dof_handler.n_dofs();
      if (contact.active())
      {
        n_unknowns += contact.create_pairs(face_vertices,
                                           vertex_dofs,
                                           dof_handler.n_dofs(),
                                           material_parameters.youngs_modulus,
                                           blank_element_size);
      }

      const std::vector<solver::MultiplierBlock> multiplier_blocks
        = contact.multiplier_blocks();
      constrained_multipliers.clear();
      for (const solver::MultiplierBlock &block : multiplier_blocks)
        for (unsigned int c = 0; c < 3; ++c)
          if (owner.count(block.displacement[c]) > 0)
            constrained_multipliers.push_back(block.multiplier[c]);
      homogeneous_constraints.clear();
      homogeneous_constraints.reinit(complete_index_set(n_unknowns));
      for (const auto &[dof, entry] : prescribed_dofs)
        homogeneous_constraints.add_line(dof);
      for (const auto dof : constrained_multipliers)
        homogeneous_constraints.add_line(dof);
      add_hanging_node_constraints(homogeneous_constraints);
      homogeneous_constraints.close();

      DynamicSparsityPattern displacement_dsp(dof_handler.n_dofs(),
                                              dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler,
                                      displacement_dsp,
                                      homogeneous_constraints,
                                      /*keep_constrained_dofs=*/true);
      DynamicSparsityPattern dsp(n_unknowns, n_unknowns);
      for (types::global_dof_index row = 0; row < dof_handler.n_dofs(); ++row)
        for (auto entry = displacement_dsp.begin(row);
             entry != displacement_dsp.end(row);
             ++entry)
          dsp.add(row, entry->column());
      contact.add_sparsity(dsp);
      sparsity_pattern.copy_from(dsp);
      system_matrix.reinit(sparsity_pattern);
      find_cell_matrix_positions();
      std::vector<bool> constrained(n_unknowns, false);
      for (const auto &line : homogeneous_constraints.get_lines())
        constrained[line.index] = true;
      linear_solver->set_multiplier_blocks(sparsity_pattern,
                                           dof_handler.n_dofs(),
                                           multiplier_blocks,
                                           contact.tool_position_unknowns(),
                                           constrained);
      system_rhs.reinit(n_unknowns);
      internal_force.reinit(n_unknowns);
      newton_unknowns.reinit(n_unknowns);
      set_up_thickness_measurement();
    }


    void
    FormingProblem::set_up_thickness_measurement()
    {
      // The thickness at every vertex is that at its initial (X, Y), found
      // on the initial surfaces of the current mesh (D72); on a refined
      // mesh the refined faces, hanging vertices included (D85).
      sheet_thickness
        = std::make_unique<SheetThickness>(triangulation, initial_vertices);
      vertex_locations.assign(initial_vertices.size(),
                              SheetThickness::Location());
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
        {
          const Point<3> &X   = initial_vertices[cell->vertex_index(v)];
          const auto location = sheet_thickness->locate(Point<2>(X[0], X[1]));
          if (!location)
            throw InputError("Geometry: the vertex at (" + std::to_string(X[0])
                             + ", " + std::to_string(X[1])
                             + ") is not over both the bottom and the top "
                               "face of the sheet mesh");
          vertex_locations[cell->vertex_index(v)] = *location;
        }
      set_up_thickness_profiles();
    }


    void
    FormingProblem::add_hanging_node_constraints(
      AffineConstraints<double> &constraints) const
    {
      for (const auto &line : hanging_node_constraints.get_lines())
      {
        constraints.add_line(line.index);
        constraints.add_entries(line.index, line.entries);
      }
    }


    void
    FormingProblem::set_up_prescribed_increment(const double old_load,
                                                const double new_load)
    {
      predictor_constraints.clear();
      for (const auto &[dof, entry] : prescribed_dofs)
      {
        const Point<3> &X = dof_initial_position[dof];
        predictor_constraints.add_line(dof);
        predictor_constraints.set_inhomogeneity(
          dof,
          prescribed.value(*entry, X, new_load)
            - prescribed.value(*entry, X, old_load));
      }
      for (const auto dof : constrained_multipliers)
        predictor_constraints.add_line(dof);
      add_hanging_node_constraints(predictor_constraints);
      predictor_constraints.close();
    }


    void
    FormingProblem::prepare_increment(const double old_load,
                                      const double new_load)
    {
      set_up_prescribed_increment(old_load, new_load);
      if (contact.active())
        contact.start_increment(old_load, new_load);
      start_load  = old_load;
      target_load = new_load;
    }


    const Vector<double> &
    FormingProblem::get_newton_unknowns() const
    {
      return state.converged_solution;
    }


    void
    FormingProblem::start_enhanced_parameters(const double ratio)
    {
      trial_enhanced_parameters = state.enhanced_parameters;
      for (fe::EnhancedParameters &cell : trial_enhanced_parameters)
        cell.scale(ratio);
    }


    void
    FormingProblem::commit_increment()
    {
      state.history             = trial_history;
      state.enhanced_parameters = trial_enhanced_parameters;
      hanging_node_constraints.distribute(newton_unknowns);
      state.previous_converged_solution = state.converged_solution;
      state.converged_solution          = newton_unknowns;
      state.last_load_increment         = target_load - start_load;
      state.load                        = target_load;
      if (contact.active())
      {
        contact.commit(newton_unknowns);
        state.contact = contact.committed_history();
      }
      move_mesh();
    }


    void
    FormingProblem::move_mesh()
    {
      // Hanging dofs follow their masters (the predictor's damped step can
      // leave them behind).
      hanging_node_constraints.distribute(newton_unknowns);
      for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
        state.total_displacement[i] += newton_unknowns[i];
      // Updated Lagrangian: the converged configuration becomes the
      // reference of the next increment (step-18 moves the vertices too).
      std::vector<bool> moved(triangulation.n_vertices(), false);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          if (!moved[cell->vertex_index(v)])
          {
            moved[cell->vertex_index(v)] = true;
            for (unsigned int c = 0; c < 3; ++c)
              cell->vertex(v)[c]
                += newton_unknowns[vertex_dofs[cell->vertex_index(v)][c]];
          }
      state.vertices = triangulation.get_vertices();
      update_cell_geometry();
      compute_thickness();
    }


    const DoFHandler<3> &
    FormingProblem::get_dof_handler() const
    {
      return dof_handler;
    }


    const Vector<double> &
    FormingProblem::get_total_displacement() const
    {
      return state.total_displacement;
    }


    const std::vector<Point<3>> &
    FormingProblem::get_initial_vertices() const
    {
      return initial_vertices;
    }


    const SimulationState &
    FormingProblem::get_state() const
    {
      return state;
    }


    const std::vector<QuadraturePointHistory> &
    FormingProblem::get_history() const
    {
      return state.history;
    }


    const std::vector<double> &
    FormingProblem::get_vertex_thickness() const
    {
      return vertex_thickness;
    }


    const SheetThickness &
    FormingProblem::get_sheet_thickness() const
    {
      return *sheet_thickness;
    }


    const std::vector<double> &
    FormingProblem::last_residuals() const
    {
      return residual_history;
    }


    const ContactCoupling &
    FormingProblem::get_contact() const
    {
      return contact;
    }


    types::global_dof_index
    FormingProblem::n_displacement_dofs() const
    {
      return dof_handler.n_dofs();
    }


    const std::vector<FormingProblem::RefinementRecord> &
    FormingProblem::refinement_records() const
    {
      return refinement_history;
    }


    const Vector<double> &
    FormingProblem::get_internal_force() const
    {
      return internal_force;
    }


    unsigned int
    FormingProblem::last_plastic_points() const
    {
      return n_plastic_points;
    }


    Tensor<1, 3>
    FormingProblem::face_reaction(const unsigned int boundary_id) const
    {
      Tensor<1, 3> reaction;
      for (const auto dof : face_dofs[boundary_id])
        reaction[dof_component[dof]] += internal_force[dof];
      return reaction;
    }
  } // namespace problem
} // namespace deepdraw
