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
    FormingProblem::start_from_converged_state()
    {
      newton_unknowns = model->state().converged_solution;
      for (types::global_dof_index i = 0;
           i < model->sheet().n_displacement_dofs();
           ++i)
        newton_unknowns[i] = 0.;
    }


    FormingProblem::IncrementOutcome
    FormingProblem::solve_increment(const double  old_load,
                                    const double  new_load,
                                    unsigned int &iterations)
    {
      const types::global_dof_index n_u = model->sheet().n_displacement_dofs();
      const state::SimulationState &committed = model->state();
      prepare_increment(old_load, new_load);
      model->linear_system().reset_reduction();
      // Displacement increment 0; contact forces and tool positions start
      // from their converged values (the tangent predictor's start).
      start_from_converged_state();
      // The element-internal unknowns start as du does: from rest, or the
      // last increment scaled (extrapolation predictor).
      const bool extrapolate = parameters.newton.predictor == "extrapolation"
                               && committed.last_load_increment > 0.;
      const double ratio
        = extrapolate ? (new_load - old_load) / committed.last_load_increment
                      : 0.;
      model->start_enhanced_parameters(ratio);
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
        model->constraints().predictor().distribute(newton_unknowns);
        const IncrementOutcome status = assemble_at(newton_unknowns, false);
        if (status == IncrementOutcome::converged)
          assembled = true;
        else if (solver::is_failed_point(status))
        {
          // Back to the tangent predictor from the converged state.
          start_from_converged_state();
          model->start_enhanced_parameters(0.);
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
                             const AffineConstraints<double> &constraints,
                             const bool                       with_matrix)
    {
      const AssemblyResult result
        = model->assemble(unknowns,
                          constraints,
                          with_matrix,
                          target_load,
                          &constraints == &model->constraints().predictor());
      progress.plastic_points = result.plastic_points;
      progress.assembly_time += result.element_time;
      progress.last_assembly_changes = result.contact_changes;
      progress.contact_changes += result.contact_changes;
      switch (result.status)
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


    // The forming problem as solver::NewtonSystem.
    FormingProblem::IncrementOutcome
    FormingProblem::assemble_at(const Vector<double> &x, const bool predictor)
    {
      return assemble(x,
                      predictor ? model->constraints().predictor()
                                : model->constraints().homogeneous(),
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
          decoupled = model->constraints().decoupled_unknowns(model->sheet());
          model->contact().add_open_multipliers(decoupled);
        }
        model->linear_system().solve(correction,
                                     model->contact().tool_position_unknowns(),
                                     decoupled);
      }
      catch (const std::exception &error)
      {
        std::cerr << "  " << error.what() << std::endl;
        return false;
      }
      (predictor ? model->constraints().predictor()
                 : model->constraints().homogeneous())
        .distribute(correction);
      progress.solve_time += timer.wall_time();
      return true;
    }


    bool
    FormingProblem::is_prescribed(const types::global_dof_index i) const
    {
      return model->constraints().predictor().is_constrained(i);
    }


    solver::ResidualMeasures
    FormingProblem::residual_measures() const
    {
      const types::global_dof_index n_u = model->sheet().n_displacement_dofs();
      const Vector<double>         &rhs = model->linear_system().rhs();
      Vector<double>                free_residual = rhs;
      model->constraints().homogeneous().set_zero(free_residual);
      // Forces are measured against the internal forces (reactions
      // included) or the largest tool force (doc/theory.md §5.2).
      double reference = model->force_scale();
      if (!(reference > 0.))
        reference = 1.;
      solver::ResidualMeasures measures;
      measures.force   = block_norm(free_residual, n_u) / reference;
      measures.contact = model->contact().residual_norm(rhs) / reference;
      measures.tool_forces_met
        = parameters.newton.tool_force_tolerance <= 0.
          || model->contact().tool_force_error(rhs, target_load, reference)
               <= parameters.newton.tool_force_tolerance;
      return measures;
    }


    double
    FormingProblem::merit() const
    {
      // The out-of-balance forces of all equations, in N (free
      // displacement rows, r F_sup, tool equations).
      const Vector<double> &rhs           = model->linear_system().rhs();
      Vector<double>        free_residual = rhs;
      model->constraints().homogeneous().set_zero(free_residual);
      const double force
        = block_norm(free_residual, model->sheet().n_displacement_dofs());
      const double contact_force = model->contact().residual_norm(rhs);
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
      return block_norm(correction, model->sheet().n_displacement_dofs());
    }


    double
    FormingProblem::relative_correction(const Vector<double> &x,
                                        const double correction_norm) const
    {
      // Against the displacement so far, not the increment alone: on tiny
      // increments (cut-backs) a 1e-6 mm correction of a slipping flange is
      // not a lack of convergence (doc/decisions.md D26).
      const types::global_dof_index n_u = model->sheet().n_displacement_dofs();
      Vector<double> displacement       = model->state().total_displacement;
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
      newton_log.add(model->state().increment_number
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
