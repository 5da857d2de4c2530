// The constraints of the Newton unknowns [du | lambda | z] (doc/theory.md
// §5): the prescribed displacements of the stage (their increments in the
// predictor, zero in the corrections), the contact forces along prescribed
// displacement components (held at zero: the constraint carries that
// force, contact::ContactCoupling::multiplier_blocks) and the hanging
// vertices of a refined mesh.
#ifndef deepdraw_discretisation_newton_constraints_h
#define deepdraw_discretisation_newton_constraints_h

#include <deal.II/lac/affine_constraints.h>
#include <deepdraw/discretisation/sheet_discretisation.h>
#include <deepdraw/process/prescribed_displacements.h>
#include <deepdraw/solver/multiplier_condensation.h>
#include <utility>
#include <vector>

namespace deepdraw
{
  namespace discretisation
  {
    class NewtonConstraints
    {
    public:
      // For the current dofs of the sheet, the prescribed displacements
      // (kept by reference until the next set_up) and the contact pairs;
      // n_unknowns counts all Newton unknowns. The homogeneous constraints
      // are then complete; a later entry overrides an earlier one where
      // two constrain the same dof. held_dofs (a release stage's supports,
      // D151) are held where they stand, after the entries.
      void
      set_up(const SheetDiscretisation                  &sheet,
             const process::PrescribedDisplacements     &prescribed,
             const std::vector<solver::MultiplierBlock> &multiplier_blocks,
             types::global_dof_index                     n_unknowns,
             const std::vector<types::global_dof_index> &held_dofs = {});

      // The predictor constraints of the increment [old_load, new_load]:
      // the prescribed dofs move by the change of their expressions.
      void
      set_increment(const SheetDiscretisation              &sheet,
                    const process::PrescribedDisplacements &prescribed,
                    double                                  old_load,
                    double                                  new_load);

      // Of the corrections (and of the whole increment's residual).
      const AffineConstraints<double> &
      homogeneous() const;
      // Of the predictor solve (set_increment).
      const AffineConstraints<double> &
      predictor() const;

      // Sets the contact forces along prescribed components to zero (after a
      // stage changed the prescribed dofs, its pairs' forces carried over).
      void
      clear_constrained_multipliers(Vector<double> &unknowns) const;

      // Unknowns whose row and column hold only their diagonal in the
      // Newton matrix: the prescribed dofs, the constrained contact
      // forces and the hanging dofs (D60).
      std::vector<types::global_dof_index>
      decoupled_unknowns(const SheetDiscretisation &sheet) const;

    private:
      // Prescribed dofs with their entry (in the set_up() argument; none:
      // held where it stands).
      std::vector<std::pair<types::global_dof_index,
                            const process::PrescribedDisplacement *>>
                                           prescribed_dofs;
      std::vector<types::global_dof_index> constrained_multipliers;
      AffineConstraints<double>            homogeneous_constraints;
      AffineConstraints<double>            predictor_constraints;
    };
  } // namespace discretisation
} // namespace deepdraw

#endif
