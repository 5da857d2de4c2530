// Viscous stabilisation of a stage (doc/theory.md §5.7, D208): a force
// c(t) V_i du_i / dt on every free displacement dof, with V_i the dof's
// vertex's share of the sheet's initial volume, du_i its displacement in
// the increment and dt the increment of t. It gives a sheet that hangs on
// a few sliding contacts (a tool retraction) the stiffness its Newton
// steps need; the stage's c(t) falls to 0 at its end, so that the state
// it ends in is in equilibrium without it.
#ifndef deepdraw_problem_viscous_stabilization_h
#define deepdraw_problem_viscous_stabilization_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/discretisation/sheet_discretisation.h>
#include <deepdraw/linear_algebra/system_matrix.h>
#include <vector>

namespace deepdraw
{
  namespace problem
  {
    using namespace dealii;

    class ViscousStabilization
    {
    public:
      // rhs -= f and, with a matrix, matrix += df/ddu (diagonal) on the
      // rows the constraints leave free, for the coefficient c (>= 0) and
      // the increment dt (> 0) of t.
      void
      add(const discretisation::SheetDiscretisation &discretisation,
          const Vector<double>                      &du,
          double                                     coefficient,
          double                                     dt,
          const AffineConstraints<double>           &constraints,
          linear_algebra::SystemMatrix              *matrix,
          Vector<double>                            &rhs);

    private:
      // V_i for every displacement dof, from the initial vertex positions
      // (so a resumed run weighs as the run it continues); recomputed when
      // the number of dofs changes (a refinement).
      void
      update_weights(const discretisation::SheetDiscretisation &discretisation);

      std::vector<double> volume_of_dof;
    };
  } // namespace problem
} // namespace deepdraw

#endif
