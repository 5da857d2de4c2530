// IncrementSolver: an increment's start (tangent or extrapolation
// predictor), the assembly of elements and contact into the Newton system,
// the model's side of solver::NewtonSystem, through which
// solver::NewtonIncrement iterates (doc/theory.md §5), and the
// re-equilibration after a mesh change (§8.3).
#include <cmath>
#include <deal.II/base/timer.h>
#include <deepdraw/problem/element_assembly.h>
#include <deepdraw/problem/increment_solver.h>
#include <deepdraw/problem/newton_measures.h>
#include <deepdraw/solver/mumps_factorization.h>
#include <iostream>

namespace deepdraw
{
  namespace problem
  {
    namespace
    {
      // For the equations as they stand, constrained rows included.
      AffineConstraints<double>
      no_constraints()
      {
        AffineConstraints<double> none;
        none.close();
        return none;
      }
    } // namespace


    IncrementSolver::IncrementSolver(SheetModel                     &model,
                                     const solver::NewtonParameters &parameters)
        : model(model)
        , parameters(parameters)
    {
      newton_unknowns.reinit(model.n_unknowns());
    }


    void
    IncrementSolver::open_log(const std::string &directory, const bool resume)
    {
      log.open(directory, resume);
    }


    void
    IncrementSolver::commit()
    {
      model.commit(newton_unknowns, start_load, target_load);
    }


    void
    IncrementSolver::reset_unknowns()
    {
      newton_unknowns = model.state().converged_solution;
    }


    const Vector<double> &
    IncrementSolver::unknowns() const
    {
      return newton_unknowns;
    }


    const NewtonProgress &
    IncrementSolver::progress() const
    {
      return newton_progress;
    }


    void
    IncrementSolver::start_timing()
    {
      newton_progress.assembly_time = newton_progress.solve_time = 0.;
    }


    void
    IncrementSolver::prepare_increment(const double old_load,
                                       const double new_load)
    {
      model.prepare_increment(old_load, new_load);
      start_load  = old_load;
      target_load = new_load;
    }


    void
    IncrementSolver::start_attempt(const double old_load,
                                   const double new_load,
                                   const double enhanced_ratio)
    {
      prepare_increment(old_load, new_load);
      // A stage's first increment (its tools start touching the sheet,
      // D92) factorises in double precision (D226).
      model.linear_system().reset_reduction(model.state().last_load_increment
                                            > 0.);
      // Displacement increment 0; contact forces and tool positions start
      // from their converged values (the tangent predictor's start).
      start_from_converged_state();
      model.start_enhanced_parameters(enhanced_ratio);
      newton_progress.start_attempt();
    }


    void
    IncrementSolver::start_from_converged_state()
    {
      newton_unknowns = model.state().converged_solution;
      for (types::global_dof_index i = 0;
           i < model.sheet().n_displacement_dofs();
           ++i)
        newton_unknowns[i] = 0.;
    }


    IncrementSolver::IncrementOutcome
    IncrementSolver::solve(const double  old_load,
                           const double  new_load,
                           unsigned int &iterations)
    {
      const types::global_dof_index n_u = model.sheet().n_displacement_dofs();
      const state::SimulationState &committed = model.state();
      // The element-internal unknowns start as du does: from rest, or the
      // last increment scaled (extrapolation predictor).
      const bool extrapolate = parameters.predictor == "extrapolation"
                               && committed.last_load_increment > 0.;
      const double ratio
        = extrapolate ? (new_load - old_load) / committed.last_load_increment
                      : 0.;
      start_attempt(old_load, new_load, ratio);

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
        model.constraints().predictor().distribute(newton_unknowns);
        const IncrementOutcome status = assemble_at(newton_unknowns, false);
        if (status == IncrementOutcome::converged)
          assembled = true;
        else if (solver::is_failed_point(status))
        {
          // Back to the tangent predictor from the converged state.
          start_from_converged_state();
          model.start_enhanced_parameters(0.);
          newton_progress.contact_changes = 0;
        }
        else
          return status;
      }

      // The stage's Newton settings: subsection Newton with its overrides.
      solver::NewtonIncrement newton(model.stage().newton);
      const IncrementOutcome  outcome
        = newton.run(*this, newton_unknowns, assembled, iterations);
      newton_progress.keep_residuals(newton);
      return outcome;
    }


    IncrementSolver::IncrementOutcome
    IncrementSolver::assemble(const Vector<double>            &unknowns,
                              const AffineConstraints<double> &constraints,
                              const bool                       with_matrix)
    {
      const AssemblyResult result
        = model.assemble(unknowns,
                         constraints,
                         with_matrix,
                         target_load,
                         &constraints == &model.constraints().predictor());
      newton_progress.plastic_points   = result.plastic_points;
      newton_progress.pending_elements = result.pending_elements;
      newton_progress.assembly_time += result.element_time;
      newton_progress.last_assembly_changes = result.contact_changes;
      newton_progress.contact_changes += result.contact_changes;
      switch (result.status)
      {
        case fe::ElementStatus::ok:
        case fe::ElementStatus::enhanced_pending:
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
    IncrementSolver::IncrementOutcome
    IncrementSolver::assemble_at(const Vector<double> &x, const bool predictor)
    {
      return assemble(x,
                      predictor ? model.constraints().predictor()
                                : model.constraints().homogeneous(),
                      true);
    }


    bool
    IncrementSolver::solve_correction(Vector<double> &correction,
                                      const bool      predictor)
    {
      Timer timer;
      try
      {
        model.solve(correction);
      }
      catch (const solver::MumpsMemoryError &)
      {
        throw; // stops the run (FormingProblem::run_stage, D177)
      }
      catch (const std::exception &error)
      {
        std::cerr << "  " << error.what() << std::endl;
        return false;
      }
      (predictor ? model.constraints().predictor()
                 : model.constraints().homogeneous())
        .distribute(correction);
      newton_progress.solve_time += timer.wall_time();
      return true;
    }


    bool
    IncrementSolver::is_prescribed(const types::global_dof_index i) const
    {
      return model.constraints().predictor().is_constrained(i);
    }


    solver::ResidualMeasures
    IncrementSolver::residual_measures() const
    {
      solver::ResidualMeasures residuals
        = measure_residuals(model,
                            target_load,
                            parameters.tool_force_tolerance);
      residuals.enhanced_converged = newton_progress.pending_elements == 0;
      return residuals;
    }


    double
    IncrementSolver::merit() const
    {
      return out_of_balance_force(model);
    }


    unsigned int
    IncrementSolver::state_changes() const
    {
      return newton_progress.last_assembly_changes;
    }


    double
    IncrementSolver::correction_norm(const Vector<double> &correction) const
    {
      return displacement_norm(model, correction);
    }


    double
    IncrementSolver::relative_correction(const Vector<double> &x,
                                         const double correction_norm) const
    {
      return correction_relative_to_displacement(model, x, correction_norm);
    }


    void
    IncrementSolver::record_iteration(const unsigned int iterations,
                                      const solver::ResidualMeasures &residuals,
                                      const double relative_correction)
    {
      log.add(model.state().increment_number
                + (newton_progress.reequilibrating ? 0 : 1),
              target_load,
              iterations,
              residuals,
              relative_correction,
              newton_progress.contact_changes
                - newton_progress.changes_reported);
      newton_progress.changes_reported = newton_progress.contact_changes;
    }


    IncrementSolver::IncrementOutcome
    IncrementSolver::reequilibrate(unsigned int &iterations)
    {
      // The transferred stress is not in equilibrium on the refined mesh
      // (nearest-point transfer, D57): Newton at the same load, from du = 0
      // and the transferred multipliers (doc/theory.md §8.3).
      start_attempt(model.state().load, model.state().load, 0.);
      iterations                      = 0;
      newton_progress.reequilibrating = true;
      IncrementOutcome outcome        = assemble_at(newton_unknowns, false);
      if (outcome == IncrementOutcome::converged)
      {
        // No stagnation cut (D89): it saves the time of an increment that
        // a cut-back would redo smaller, but a re-equilibration has no
        // smaller step; it may use all of Maximum iterations.
        solver::NewtonParameters settings = model.stage().newton;
        settings.stagnation_iterations    = 0;
        solver::NewtonIncrement newton(settings);
        outcome = newton.run(*this, newton_unknowns, true, iterations);
        newton_progress.keep_residuals(newton);
      }
      newton_progress.reequilibrating = false;
      if (outcome == IncrementOutcome::converged)
        model.commit_equilibrium(newton_unknowns);
      return outcome;
    }


    bool
    IncrementSolver::assemble_system(const Vector<double> &unknowns)
    {
      return assemble(unknowns, no_constraints(), true)
             == IncrementOutcome::converged;
    }


    bool
    IncrementSolver::evaluate_residual(const Vector<double> &unknowns,
                                       Vector<double>       &residual,
                                       FullMatrix<double>   *tangent)
    {
      const IncrementOutcome status
        = assemble(unknowns, no_constraints(), tangent != nullptr);
      // Without constraints rhs = -r for all equations, contact included.
      residual = model.linear_system().rhs();
      residual *= -1.;
      if (tangent != nullptr)
        model.linear_system().copy_to(*tangent);
      return status == IncrementOutcome::converged;
    }
  } // namespace problem
} // namespace deepdraw
