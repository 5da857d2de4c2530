// Parameters, set-up and the increment loop of FormingProblem; the assembly
// is in forming_problem_assembly.cc, the output in forming_problem_output.cc.
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/problem/forming_problem.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>

namespace deepdraw
{
  namespace problem
  {
    void
    FormingProblem::declare_parameters(ParameterHandler &prm)
    {
      BlankGeometry::declare_parameters(prm);
      prm.enter_subsection("Material");
      material::MaterialParameters::declare_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Finite element");
      prm.declare_entry("Integration",
                        "selective reduced",
                        Patterns::Selection("selective reduced|full"),
                        "'selective reduced': 2x2x2 Gauss points with the "
                        "hydrostatic part of the gradients taken at the cell "
                        "centre (no volumetric locking); 'full': plain "
                        "2x2x2 Gauss integration (locks under isochoric "
                        "plastic flow; for comparison).");
      prm.leave_subsection();
      PrescribedDisplacements::declare_parameters(prm);
      solver::IncrementControlParameters::declare_parameters(prm);
      solver::NewtonParameters::declare_parameters(prm);
      solver::LinearSolverParameters::declare_parameters(prm);
      io::OutputParameters::declare_parameters(prm);
    }



    FormingProblem::FormingProblem(ParameterHandler &prm)
      : fe(FE_Q<3>(1), 3)
      , dof_handler(triangulation)
      , fe_scalar(1)
      , scalar_dof_handler(triangulation)
    {
      geometry.parse_parameters(prm);
      prm.enter_subsection("Material");
      material_parameters.parse_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Finite element");
      selective_reduced_integration =
        (prm.get("Integration") == "selective reduced");
      prm.leave_subsection();
      prescribed.parse_parameters(prm,
                                  geometry.symmetry_plane_x,
                                  geometry.symmetry_plane_y);
      increment_parameters.parse_parameters(prm);
      newton_parameters.parse_parameters(prm);
      linear_solver_parameters.parse_parameters(prm);
      output_parameters.parse_parameters(prm);

      material = std::make_unique<material::HillPlasticity>(material_parameters);
      linear_solver =
        std::make_unique<solver::LinearSolver>(linear_solver_parameters);
      setup_system();
    }



    void
    FormingProblem::setup_system()
    {
      geometry.create_mesh(triangulation, vertex_column, vertex_layer);
      initial_vertices = triangulation.get_vertices();
      dof_handler.distribute_dofs(fe);
      scalar_dof_handler.distribute_dofs(fe_scalar);

      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          local_component[i] = fe.system_to_component_index(i).first;
          local_node[i]      = fe.system_to_component_index(i).second;
        }

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
              dof_initial_position[dof] = cell->vertex(v);
              dof_component[dof]        = c;
            }

      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            for (const unsigned int v : face->vertex_indices())
              for (unsigned int c = 0; c < 3; ++c)
                face_dofs[face->boundary_id()].push_back(
                  face->vertex_dof_index(v, c));
      for (auto &dofs : face_dofs)
        {
          std::sort(dofs.begin(), dofs.end());
          dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
        }

      // Prescribed dofs; a later entry overrides an earlier one.
      std::map<types::global_dof_index, const PrescribedDisplacement *> owner;
      for (const PrescribedDisplacement &entry : prescribed.entries)
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == entry.boundary_id)
              for (const unsigned int v : face->vertex_indices())
                owner[face->vertex_dof_index(v, entry.component)] = &entry;
      prescribed_dofs.assign(owner.begin(), owner.end());

      homogeneous_constraints.clear();
      for (const auto &[dof, entry] : prescribed_dofs)
        homogeneous_constraints.add_line(dof);
      homogeneous_constraints.close();

      DynamicSparsityPattern dsp(dof_handler.n_dofs(), dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler,
                                      dsp,
                                      homogeneous_constraints,
                                      /*keep_constrained_dofs=*/true);
      sparsity_pattern.copy_from(dsp);
      system_matrix.reinit(sparsity_pattern);
      system_rhs.reinit(dof_handler.n_dofs());
      internal_force.reinit(dof_handler.n_dofs());
      total_displacement.reinit(dof_handler.n_dofs());
      displacement_increment.reinit(dof_handler.n_dofs());

      history.assign(triangulation.n_active_cells() * fe::n_weighted_points,
                     QuadraturePointHistory());
      trial_history = history;

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
      predictor_constraints.close();
    }



    std::string
    FormingProblem::describe(const IncrementOutcome outcome)
    {
      switch (outcome)
        {
          case IncrementOutcome::converged:
            return "converged";
          case IncrementOutcome::too_many_iterations:
            return "too many Newton iterations";
          case IncrementOutcome::diverged:
            return "growing residual";
          case IncrementOutcome::not_a_number:
            return "residual is not a number";
          case IncrementOutcome::inverted_element:
            return "inverted element (det F <= 0)";
          case IncrementOutcome::return_mapping_failed:
            return "local return mapping failed";
          case IncrementOutcome::linear_solver_failed:
            return "linear solver failed";
        }
      return "unknown";
    }



    FormingProblem::IncrementOutcome
    FormingProblem::solve_increment(const double  old_load,
                                    const double  new_load,
                                    unsigned int &iterations)
    {
      set_up_prescribed_increment(old_load, new_load);
      displacement_increment = 0.;
      residual_history.clear();
      Vector<double> correction(dof_handler.n_dofs());
      double         correction_norm = 0.;
      double         smallest_residual = std::numeric_limits<double>::max();

      for (iterations = 0;; ++iterations)
        {
          // Iteration 0 is the tangent predictor (reference Eq. 13): the
          // prescribed increment enters through inhomogeneous constraints.
          const AffineConstraints<double> &constraints =
            iterations == 0 ? predictor_constraints : homogeneous_constraints;
          const IncrementOutcome status =
            assemble(displacement_increment, constraints, true);
          if (status != IncrementOutcome::converged)
            return status;

          if (iterations > 0)
            {
              Vector<double> free_residual = system_rhs;
              homogeneous_constraints.set_zero(free_residual);
              const double reference = internal_force.l2_norm();
              const double force_residual =
                reference > 0. ? free_residual.l2_norm() / reference :
                                 free_residual.l2_norm();
              const double increment_norm = displacement_increment.l2_norm();
              const double relative_correction =
                increment_norm > 0. ? correction_norm / increment_norm : 0.;
              residual_history.push_back(force_residual);
              newton_file.add_row({double(increment_number + 1),
                                   new_load,
                                   double(iterations),
                                   force_residual,
                                   relative_correction});

              if (!std::isfinite(force_residual))
                return IncrementOutcome::not_a_number;
              if (force_residual <= newton_parameters.force_tolerance
                  && relative_correction
                       <= newton_parameters.correction_tolerance)
                return IncrementOutcome::converged;
              smallest_residual = std::min(smallest_residual, force_residual);
              if (force_residual
                  > newton_parameters.divergence_ratio * smallest_residual)
                return IncrementOutcome::diverged;
              if (iterations >= newton_parameters.maximum_iterations)
                return IncrementOutcome::too_many_iterations;
            }

          Timer timer;
          try
            {
              linear_solver->solve(system_matrix, system_rhs, correction);
            }
          catch (const std::exception &error)
            {
              std::cerr << "  " << error.what() << std::endl;
              return IncrementOutcome::linear_solver_failed;
            }
          constraints.distribute(correction);
          solve_time += timer.wall_time();
          correction_norm = correction.l2_norm();
          if (!std::isfinite(correction_norm))
            return IncrementOutcome::not_a_number;
          displacement_increment += correction;
        }
    }



    void
    FormingProblem::commit_increment()
    {
      history = trial_history;
      total_displacement += displacement_increment;
      // Updated Lagrangian: the converged configuration becomes the
      // reference of the next increment (step-18 moves the vertices too).
      std::vector<bool> moved(triangulation.n_vertices(), false);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          if (!moved[cell->vertex_index(v)])
            {
              moved[cell->vertex_index(v)] = true;
              for (unsigned int c = 0; c < 3; ++c)
                cell->vertex(v)[c] +=
                  displacement_increment[vertex_dofs[cell->vertex_index(v)][c]];
            }
      update_cell_geometry();
      compute_thickness();
    }



    void
    FormingProblem::run()
    {
      open_output_files();
      write_vtu(0.);

      std::vector<double> landing_loads;
      if (output_parameters.output_interval > 0.)
        for (double load = output_parameters.output_interval;
             load < increment_parameters.final_load;
             load += output_parameters.output_interval)
          landing_loads.push_back(load);
      solver::IncrementControl control(increment_parameters, landing_loads);

      std::cout << "deepdraw: " << triangulation.n_active_cells()
                << " cells, " << dof_handler.n_dofs() << " unknowns, "
                << (selective_reduced_integration ? "selective reduced" :
                                                    "full")
                << " integration" << std::endl;

      Timer run_timer;
      while (!control.finished())
        {
          const double old_load = control.current_load();
          const double new_load = old_load + control.next_increment();
          assembly_time         = 0.;
          solve_time            = 0.;
          Timer        increment_timer;
          unsigned int iterations = 0;
          const IncrementOutcome outcome =
            solve_increment(old_load, new_load, iterations);

          if (outcome != IncrementOutcome::converged)
            {
              std::cout << "  load " << new_load << ": " << describe(outcome)
                        << ", cutting the increment back" << std::endl;
              trial_history = history;
              if (!control.cut_back())
                throw RunFailure(
                  "the increment from load " + std::to_string(old_load)
                  + " could not be completed (" + describe(outcome)
                  + ") even after "
                  + std::to_string(control.cut_backs_of_current_increment())
                  + " cut-backs; results up to load "
                  + std::to_string(old_load) + " are in "
                  + output_parameters.output_directory);
              continue;
            }

          const unsigned int cut_backs = control.cut_backs_of_current_increment();
          control.accept(iterations);
          commit_increment();
          ++increment_number;

          Timer output_timer;
          const bool at_output =
            output_parameters.output_interval <= 0.
            || control.finished()
            || std::find_if(landing_loads.begin(),
                            landing_loads.end(),
                            [&](const double l) {
                              return std::abs(l - new_load)
                                     < 1e-9 * std::max(1., std::abs(l));
                            })
                 != landing_loads.end();
          if (at_output)
            write_vtu(new_load);
          write_increment_tables(new_load);
          const double output_time = output_timer.wall_time();

          statistics_file.add_row(
            {double(increment_number),
             new_load,
             new_load - old_load,
             double(iterations),
             double(cut_backs),
             residual_history.empty() ? 0. : residual_history.back(),
             double(n_plastic_points),
             assembly_time,
             solve_time,
             output_time,
             increment_timer.wall_time()});

          std::cout << "increment " << std::setw(4) << increment_number
                    << "  load " << std::setw(10) << std::setprecision(5)
                    << new_load << "  iterations " << std::setw(2)
                    << iterations << "  cut-backs " << cut_backs
                    << "  residual " << std::setprecision(2)
                    << std::scientific
                    << (residual_history.empty() ? 0. :
                                                   residual_history.back())
                    << std::defaultfloat << "  plastic points "
                    << n_plastic_points << "  time " << std::setprecision(3)
                    << increment_timer.wall_time() << " s" << std::endl;
        }
      std::cout << "deepdraw: finished at load " << control.current_load()
                << " after " << increment_number << " increments in "
                << run_timer.wall_time() << " s; results in "
                << output_parameters.output_directory << std::endl;
    }



    const DoFHandler<3> &
    FormingProblem::get_dof_handler() const
    {
      return dof_handler;
    }



    const Vector<double> &
    FormingProblem::get_total_displacement() const
    {
      return total_displacement;
    }



    const std::vector<Point<3>> &
    FormingProblem::get_initial_vertices() const
    {
      return initial_vertices;
    }



    const std::vector<QuadraturePointHistory> &
    FormingProblem::get_history() const
    {
      return history;
    }



    const std::vector<double> &
    FormingProblem::get_column_thickness() const
    {
      return column_thickness;
    }



    const std::vector<unsigned int> &
    FormingProblem::get_vertex_column() const
    {
      return vertex_column;
    }



    const std::vector<double> &
    FormingProblem::last_residuals() const
    {
      return residual_history;
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
