// One increment of FormingProblem: its start (tangent or extrapolation
// predictor), the assembly of elements and contact into the Newton system,
// and the problem's side of solver::NewtonSystem, through which
// solver::NewtonIncrement iterates (doc/theory.md §5).
#include <cmath>
#include <deal.II/base/timer.h>
#include <deepdraw/problem/element_assembly.h>
#include <deepdraw/problem/forming_problem.h>
#include <iostream>

namespace deepdraw
{
  namespace problem
  {
    namespace
    {
      // l2 norm of the first n entries (the displacement block).
      double
      block_norm(const Vector<double> &vector, const types::global_dof_index n)
      {
        double sum = 0.;
        for (types::global_dof_index i = 0; i < n; ++i)
          sum += vector[i] * vector[i];
        return std::sqrt(sum);
      }
    } // namespace


    void
    FormingProblem::prepare_increment(const double old_load,
                                      const double new_load)
    {
      constraints.set_increment(discretisation,
                                stage().prescribed,
                                old_load,
                                new_load);
      if (contact_coupling.active())
        contact_coupling.start_increment(old_load, new_load);
      start_load  = old_load;
      target_load = new_load;
    }


    void
    FormingProblem::start_enhanced_parameters(const double ratio)
    {
      trial_enhanced_parameters = committed.enhanced_parameters;
      for (fe::EnhancedParameters &cell : trial_enhanced_parameters)
        cell.scale(ratio);
    }


    FormingProblem::IncrementOutcome
    FormingProblem::solve_increment(const double  old_load,
                                    const double  new_load,
                                    unsigned int &iterations)
    {
      const types::global_dof_index n_u = discretisation.n_displacement_dofs();
      prepare_increment(old_load, new_load);
      linear_system->reset_reduction();
      // Displacement increment 0; contact forces and tool positions start
      // from their converged values (the tangent predictor's start).
      const auto start_from_converged_state = [&]()
      {
        newton_unknowns = committed.converged_solution;
        for (types::global_dof_index i = 0; i < n_u; ++i)
          newton_unknowns[i] = 0.;
      };
      start_from_converged_state();
      // The element-internal unknowns start as du does: from rest, or the
      // last increment scaled (extrapolation predictor).
      const bool extrapolate = parameters.newton.predictor == "extrapolation"
                               && committed.last_load_increment > 0.;
      const double ratio
        = extrapolate ? (new_load - old_load) / committed.last_load_increment
                      : 0.;
      start_enhanced_parameters(ratio);
      progress.start_attempt();

      // Extrapolation predictor: the last increment scaled to this one
      // (du, and lambda, z linearly in the load), prescribed dofs exact.
      // Without a linear solve, so the checks count one solve fewer.
      bool assembled = false;
      if (extrapolate)
      {
        const Vector<double> &last     = committed.converged_solution;
        const Vector<double> &previous = committed.previous_converged_solution;
        for (types::global_dof_index i = 0; i < newton_unknowns.size(); ++i)
          newton_unknowns[i] = i < n_u
                                 ? ratio * last[i]
                                 : last[i] + ratio * (last[i] - previous[i]);
        constraints.predictor().distribute(newton_unknowns);
        const IncrementOutcome status = assemble_at(newton_unknowns, false);
        if (status == IncrementOutcome::converged)
          assembled = true;
        else if (solver::is_failed_point(status))
        {
          // Back to the tangent predictor from the converged state.
          start_from_converged_state();
          start_enhanced_parameters(0.);
          progress.contact_changes = 0;
        }
        else
          return status;
      }

      solver::NewtonIncrement newton(parameters.newton);
      const IncrementOutcome  outcome
        = newton.run(*this, newton_unknowns, assembled, iterations);
      progress.keep_residuals(newton);
      return outcome;
    }


    FormingProblem::IncrementOutcome
    FormingProblem::assemble(const Vector<double>            &unknowns,
                             const AffineConstraints<double> &constraints_used,
                             const bool                       with_matrix)
    {
      Timer timer;
      // On a refined mesh the hanging dofs are evaluated from their masters
      // (an iterate may not satisfy the constraints, e.g. after the
      // predictor's damped step).
      const AffineConstraints<double> &hanging
        = discretisation.hanging_node_constraints();
      Vector<double> consistent;
      if (hanging.n_constraints() > 0)
      {
        consistent = unknowns;
        hanging.distribute(consistent);
      }
      const Vector<double> &du
        = hanging.n_constraints() > 0 ? consistent : unknowns;
      linear_system->zero(with_matrix);
      internal_forces = 0.;
      linear_algebra::SystemMatrix *matrix
        = with_matrix ? &linear_system->matrix() : nullptr;
      const ElementAssemblyResult elements
        = assemble_elements(*element,
                            discretisation,
                            du,
                            constraints_used,
                            committed.history,
                            trial_history,
                            trial_enhanced_parameters,
                            matrix,
                            linear_system->rhs(),
                            internal_forces);
      progress.plastic_points = elements.plastic_points;
      progress.assembly_time += timer.wall_time();

      // Contact forces and their constraints, after the elements so that
      // the assembly time excludes the contact search.
      progress.last_assembly_changes = 0;
      if (contact_coupling.active())
        progress.last_assembly_changes = contact_coupling.assemble(
          discretisation.triangulation().get_vertices(),
          du,
          constraints_used,
          matrix,
          linear_system->rhs(),
          target_load,
          &constraints_used == &constraints.predictor());
      progress.contact_changes += progress.last_assembly_changes;

      switch (elements.status)
      {
        case fe::ElementStatus::ok:
          return IncrementOutcome::converged;
        case fe::ElementStatus::inverted:
          return IncrementOutcome::inverted_element;
        case fe::ElementStatus::return_mapping_failed:
          return IncrementOutcome::return_mapping_failed;
        case fe::ElementStatus::enhanced_not_converged:
          return IncrementOutcome::enhanced_not_converged;
      }
      return IncrementOutcome::return_mapping_failed;
    }


    bool
    FormingProblem::assemble_system(const Vector<double> &unknowns)
    {
      AffineConstraints<double> none;
      none.close();
      return assemble(unknowns, none, true) == IncrementOutcome::converged;
    }


    bool
    FormingProblem::evaluate_residual(const Vector<double> &unknowns,
                                      Vector<double>       &residual,
                                      FullMatrix<double>   *tangent)
    {
      AffineConstraints<double> none;
      none.close();
      const IncrementOutcome status
        = assemble(unknowns, none, tangent != nullptr);
      // Without constraints rhs = -r for all equations, contact included.
      residual = linear_system->rhs();
      residual *= -1.;
      if (tangent != nullptr)
        linear_system->copy_to(*tangent);
      return status == IncrementOutcome::converged;
    }


    // The forming problem as solver::NewtonSystem.
    FormingProblem::IncrementOutcome
    FormingProblem::assemble_at(const Vector<double> &x, const bool predictor)
    {
      return assemble(x,
                      predictor ? constraints.predictor()
                                : constraints.homogeneous(),
                      true);
    }


    bool
    FormingProblem::solve_correction(Vector<double> &correction,
                                     const bool      predictor)
    {
      Timer timer;
      try
      {
        // Rows and columns that hold only their diagonal: constrained dofs
        // (distribute() sets them afterwards) and the multipliers of open
        // pairs (D60).
        std::vector<types::global_dof_index> decoupled;
        if (parameters.linear_solver.leave_out_decoupled)
        {
          decoupled = constraints.decoupled_unknowns(discretisation);
          contact_coupling.add_open_multipliers(decoupled);
        }
        linear_system->solve(correction,
                             contact_coupling.tool_position_unknowns(),
                             decoupled);
      }
      catch (const std::exception &error)
      {
        std::cerr << "  " << error.what() << std::endl;
        return false;
      }
      (predictor ? constraints.predictor() : constraints.homogeneous())
        .distribute(correction);
      progress.solve_time += timer.wall_time();
      return true;
    }


    bool
    FormingProblem::is_prescribed(const types::global_dof_index i) const
    {
      return constraints.predictor().is_constrained(i);
    }


    solver::ResidualMeasures
    FormingProblem::residual_measures() const
    {
      const types::global_dof_index n_u = discretisation.n_displacement_dofs();
      const Vector<double>         &rhs = linear_system->rhs();
      Vector<double>                free_residual = rhs;
      constraints.homogeneous().set_zero(free_residual);
      // Forces are measured against the internal forces (reactions
      // included) or the largest tool force (doc/theory.md §5.2).
      double reference = block_norm(internal_forces, n_u);
      for (const Tensor<1, 3> &force : contact_coupling.tool_forces())
        reference = std::max(reference, force.norm());
      if (!(reference > 0.))
        reference = 1.;
      solver::ResidualMeasures measures;
      measures.force   = block_norm(free_residual, n_u) / reference;
      measures.contact = contact_coupling.residual_norm(rhs) / reference;
      measures.tool_forces_met
        = parameters.newton.tool_force_tolerance <= 0.
          || contact_coupling.tool_force_error(rhs, target_load, reference)
               <= parameters.newton.tool_force_tolerance;
      return measures;
    }


    double
    FormingProblem::merit() const
    {
      // The out-of-balance forces of all equations, in N (free
      // displacement rows, r F_sup, tool equations).
      const Vector<double> &rhs           = linear_system->rhs();
      Vector<double>        free_residual = rhs;
      constraints.homogeneous().set_zero(free_residual);
      const double force
        = block_norm(free_residual, discretisation.n_displacement_dofs());
      const double contact_force = contact_coupling.residual_norm(rhs);
      return std::sqrt(force * force + contact_force * contact_force);
    }


    unsigned int
    FormingProblem::state_changes() const
    {
      return progress.last_assembly_changes;
    }


    double
    FormingProblem::correction_norm(const Vector<double> &correction) const
    {
      return block_norm(correction, discretisation.n_displacement_dofs());
    }


    double
    FormingProblem::relative_correction(const Vector<double> &x,
                                        const double correction_norm) const
    {
      // Against the displacement so far, not the increment alone: on tiny
      // increments (cut-backs) a 1e-6 mm correction of a slipping flange is
      // not a lack of convergence (doc/decisions.md D26).
      const types::global_dof_index n_u = discretisation.n_displacement_dofs();
      Vector<double>                displacement = committed.total_displacement;
      for (types::global_dof_index i = 0; i < n_u; ++i)
        displacement[i] += x[i];
      const double displacement_norm
        = std::max(block_norm(x, n_u), block_norm(displacement, n_u));
      return displacement_norm > 0. ? correction_norm / displacement_norm : 0.;
    }


    void
    FormingProblem::record_iteration(const unsigned int              iterations,
                                     const solver::ResidualMeasures &residuals,
                                     const double relative_correction)
    {
      newton_log.add(committed.increment_number
                       + (progress.reequilibrating ? 0 : 1),
                     target_load,
                     iterations,
                     residuals,
                     relative_correction,
                     progress.contact_changes - progress.changes_reported);
      progress.changes_reported = progress.contact_changes;
    }
  } // namespace problem
} // namespace deepdraw
