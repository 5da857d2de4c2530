// One increment of FormingProblem: its start (tangent or extrapolation
// predictor) and the problem's side of solver::NewtonSystem, through which
// solver::NewtonIncrement iterates (doc/theory.md §5).
#include <cmath>
#include <deal.II/base/timer.h>
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


    FormingProblem::IncrementOutcome
    FormingProblem::solve_increment(const double  old_load,
                                    const double  new_load,
                                    unsigned int &iterations)
    {
      const types::global_dof_index n_u = dof_handler.n_dofs();
      prepare_increment(old_load, new_load);
      linear_solver->reset_reduction();
      // Displacement increment 0; contact forces and tool positions start
      // from their converged values (the tangent predictor's start).
      const auto start_from_converged_state = [&]()
      {
        newton_unknowns = state.converged_solution;
        for (types::global_dof_index i = 0; i < n_u; ++i)
          newton_unknowns[i] = 0.;
      };
      start_from_converged_state();
      // The element-internal unknowns start as du does: from rest, or the
      // last increment scaled (extrapolation predictor).
      const bool extrapolate = newton_parameters.predictor == "extrapolation"
                               && state.last_load_increment > 0.;
      start_enhanced_parameters(
        extrapolate ? (new_load - old_load) / state.last_load_increment : 0.);
      residual_history.clear();
      contact_residual_history.clear();
      contact_changes  = 0;
      changes_reported = 0;

      // Extrapolation predictor: the last increment scaled to this one
      // (du, and lambda, z linearly in the load), prescribed dofs exact.
      // Without a linear solve, so the checks count one solve fewer.
      bool assembled = false;
      if (extrapolate)
      {
        const double ratio = (new_load - old_load) / state.last_load_increment;
        for (types::global_dof_index i = 0; i < newton_unknowns.size(); ++i)
          newton_unknowns[i]
            = i < n_u ? ratio * state.converged_solution[i]
                      : state.converged_solution[i]
                          + ratio
                              * (state.converged_solution[i]
                                 - state.previous_converged_solution[i]);
        predictor_constraints.distribute(newton_unknowns);
        const IncrementOutcome status = assemble_at(newton_unknowns, false);
        if (status == IncrementOutcome::converged)
          assembled = true;
        else if (solver::is_failed_point(status))
        {
          // Back to the tangent predictor from the converged state.
          start_from_converged_state();
          start_enhanced_parameters(0.);
          contact_changes = 0;
        }
        else
          return status;
      }

      solver::NewtonIncrement newton(newton_parameters);
      const IncrementOutcome  outcome
        = newton.run(*this, newton_unknowns, assembled, iterations);
      residual_history         = newton.force_residuals();
      contact_residual_history = newton.contact_residuals();
      return outcome;
    }


    // The forming problem as solver::NewtonSystem: the Newton unknowns are
    // newton_unknowns = [du | lambda | z].
    FormingProblem::IncrementOutcome
    FormingProblem::assemble_at(const Vector<double> &x, const bool predictor)
    {
      return assemble(x,
                      predictor ? predictor_constraints
                                : homogeneous_constraints,
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
        if (linear_solver_parameters.leave_out_decoupled)
        {
          for (const auto &[dof, entry] : prescribed_dofs)
            decoupled.push_back(dof);
          decoupled.insert(decoupled.end(),
                           constrained_multipliers.begin(),
                           constrained_multipliers.end());
          for (const auto &line : hanging_node_constraints.get_lines())
            decoupled.push_back(line.index);
          contact.add_open_multipliers(decoupled);
        }
        linear_solver->solve(system_matrix,
                             system_rhs,
                             correction,
                             contact.tool_position_unknowns(),
                             decoupled);
      }
      catch (const std::exception &error)
      {
        std::cerr << "  " << error.what() << std::endl;
        return false;
      }
      (predictor ? predictor_constraints : homogeneous_constraints)
        .distribute(correction);
      solve_time += timer.wall_time();
      return true;
    }


    bool
    FormingProblem::is_prescribed(const types::global_dof_index i) const
    {
      return predictor_constraints.is_constrained(i);
    }


    solver::ResidualMeasures
    FormingProblem::residual_measures() const
    {
      const types::global_dof_index n_u           = dof_handler.n_dofs();
      Vector<double>                free_residual = system_rhs;
      homogeneous_constraints.set_zero(free_residual);
      // Forces are measured against the internal forces (reactions
      // included) or the largest tool force (doc/theory.md §5.2).
      double reference = block_norm(internal_force, n_u);
      for (const Tensor<1, 3> &force : contact.tool_forces())
        reference = std::max(reference, force.norm());
      if (!(reference > 0.))
        reference = 1.;
      solver::ResidualMeasures measures;
      measures.force   = block_norm(free_residual, n_u) / reference;
      measures.contact = contact.residual_norm(system_rhs) / reference;
      measures.tool_forces_met
        = newton_parameters.tool_force_tolerance <= 0.
          || contact.tool_force_error(system_rhs, target_load, reference)
               <= newton_parameters.tool_force_tolerance;
      return measures;
    }


    double
    FormingProblem::merit() const
    {
      // The out-of-balance forces of all equations, in N (free
      // displacement rows, r F_sup, tool equations).
      Vector<double> free_residual = system_rhs;
      homogeneous_constraints.set_zero(free_residual);
      const double force = block_norm(free_residual, dof_handler.n_dofs());
      const double contact_force = contact.residual_norm(system_rhs);
      return std::sqrt(force * force + contact_force * contact_force);
    }


    unsigned int
    FormingProblem::state_changes() const
    {
      return last_assembly_changes;
    }


    double
    FormingProblem::correction_norm(const Vector<double> &correction) const
    {
      return block_norm(correction, dof_handler.n_dofs());
    }


    double
    FormingProblem::relative_correction(const Vector<double> &x,
                                        const double correction_norm) const
    {
      // Against the displacement so far, not the increment alone: on tiny
      // increments (cut-backs) a 1e-6 mm correction of a slipping flange is
      // not a lack of convergence (doc/decisions.md D26).
      const types::global_dof_index n_u          = dof_handler.n_dofs();
      Vector<double>                displacement = state.total_displacement;
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
      newton_file.add_row(
        {double(state.increment_number + (reequilibrating ? 0 : 1)),
         target_load,
         double(iterations),
         residuals.force,
         residuals.contact,
         relative_correction,
         double(contact_changes - changes_reported)});
      changes_reported = contact_changes;
    }
  } // namespace problem
} // namespace deepdraw
