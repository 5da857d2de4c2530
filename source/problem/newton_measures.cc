#include <algorithm>
#include <cmath>
#include <deepdraw/problem/newton_measures.h>

namespace deepdraw
{
  namespace problem
  {
    namespace
    {
      // The last assembly's right-hand side without the constrained rows.
      Vector<double>
      free_residual(const SheetModel &model)
      {
        Vector<double> residual = model.linear_system().rhs();
        model.constraints().homogeneous().set_zero(residual);
        return residual;
      }
    } // namespace


    double
    displacement_norm(const SheetModel &model, const Vector<double> &vector)
    {
      const types::global_dof_index n   = model.sheet().n_displacement_dofs();
      double                        sum = 0.;
      for (types::global_dof_index i = 0; i < n; ++i)
        sum += vector[i] * vector[i];
      return std::sqrt(sum);
    }


    solver::ResidualMeasures
    measure_residuals(const SheetModel &model,
                      const double      target_load,
                      const double      tool_force_tolerance)
    {
      const Vector<double> &rhs = model.linear_system().rhs();
      // Forces are measured against the internal forces (reactions
      // included) or the largest tool force (doc/theory.md §5.2).
      double reference = model.force_scale();
      if (!(reference > 0.))
        reference = 1.;
      solver::ResidualMeasures measures;
      measures.force
        = displacement_norm(model, free_residual(model)) / reference;
      measures.contact = model.contact().residual_norm(rhs) / reference;
      measures.tool_forces_met
        = tool_force_tolerance <= 0.
          || model.contact().tool_force_error(rhs, target_load, reference)
               <= tool_force_tolerance;
      return measures;
    }


    double
    out_of_balance_force(const SheetModel &model)
    {
      const double force = displacement_norm(model, free_residual(model));
      const double contact_force
        = model.contact().residual_norm(model.linear_system().rhs());
      return std::sqrt(force * force + contact_force * contact_force);
    }


    double
    correction_relative_to_displacement(const SheetModel     &model,
                                        const Vector<double> &x,
                                        const double          correction_norm)
    {
      // Against the displacement so far, not the increment alone: on tiny
      // increments (cut-backs) a 1e-6 mm correction of a slipping flange is
      // not a lack of convergence (doc/decisions.md D26).
      const types::global_dof_index n = model.sheet().n_displacement_dofs();
      Vector<double> displacement     = model.state().total_displacement;
      for (types::global_dof_index i = 0; i < n; ++i)
        displacement[i] += x[i];
      const double displacement_size
        = std::max(displacement_norm(model, x),
                   displacement_norm(model, displacement));
      return displacement_size > 0. ? correction_norm / displacement_size : 0.;
    }
  } // namespace problem
} // namespace deepdraw
