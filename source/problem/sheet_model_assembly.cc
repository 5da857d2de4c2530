// SheetModel: one increment's equations, the elements (element_assembly.h)
// and the contact coupling assembled into the Newton system, and its solve.
#include <deal.II/base/timer.h>
#include <deepdraw/problem/element_assembly.h>
#include <deepdraw/problem/sheet_model.h>

namespace deepdraw
{
  namespace problem
  {
    void
    SheetModel::prepare_increment(const double old_load, const double new_load)
    {
      newton_constraints.set_increment(discretisation,
                                       stage().prescribed,
                                       old_load,
                                       new_load);
      if (contact_coupling.active())
        contact_coupling.start_increment(old_load, new_load);
    }


    void
    SheetModel::start_enhanced_parameters(const double ratio)
    {
      trial_enhanced_parameters = committed.enhanced_parameters;
      for (fe::EnhancedParameters &cell : trial_enhanced_parameters)
        cell.scale(ratio);
    }


    AssemblyResult
    SheetModel::assemble(const Vector<double>            &unknowns,
                         const AffineConstraints<double> &constraints_used,
                         const bool                       with_matrix,
                         const double                     load,
                         const bool                       predictor)
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
      system->zero(with_matrix);
      internal_forces = 0.;
      linear_algebra::SystemMatrix *matrix
        = with_matrix ? &system->matrix() : nullptr;
      const ElementAssemblyResult elements
        = assemble_elements(*element,
                            discretisation,
                            du,
                            constraints_used,
                            committed.history,
                            trial_history,
                            trial_enhanced_parameters,
                            matrix,
                            system->rhs(),
                            internal_forces);
      if (stage().releases_forces())
        add_release_loads(constraints_used, load, system->rhs());
      const double viscosity = stage().viscous_coefficient(load);
      if (viscosity > 0. && load > committed.load)
        viscous_stabilization.add(discretisation,
                                  du,
                                  viscosity,
                                  load - committed.load,
                                  constraints_used,
                                  matrix,
                                  system->rhs());
      AssemblyResult result;
      result.status           = elements.status;
      result.plastic_points   = elements.plastic_points;
      result.pending_elements = elements.pending_elements;
      result.element_time     = timer.wall_time();
      // Contact forces and their constraints, after the elements so that
      // the element time excludes the contact search.
      if (contact_coupling.active())
        result.contact_changes = contact_coupling.assemble(
          discretisation.triangulation().get_vertices(),
          du,
          constraints_used,
          matrix,
          system->rhs(),
          load,
          predictor);
      return result;
    }


    void
    SheetModel::solve(Vector<double> &correction)
    {
      // Rows and columns that hold only their diagonal: constrained dofs
      // (distribute() sets them afterwards) and the multipliers of open
      // pairs (D60).
      std::vector<types::global_dof_index> decoupled;
      if (parameters.linear_solver.leave_out_decoupled)
      {
        decoupled = newton_constraints.decoupled_unknowns(discretisation);
        contact_coupling.add_open_multipliers(decoupled);
      }
      system->solve(correction,
                    contact_coupling.tool_position_unknowns(),
                    decoupled);
    }
  } // namespace problem
} // namespace deepdraw
