// The measures of a Newton iterate of the sheet model that
// solver::NewtonIncrement tests and compares (doc/theory.md §5.2): the
// relative residuals, the out-of-balance force of all equations and the
// size of a correction. Read from the last assembly's right-hand side.
#ifndef deepdraw_problem_newton_measures_h
#define deepdraw_problem_newton_measures_h

#include <deal.II/lac/vector.h>
#include <deepdraw/problem/sheet_model.h>
#include <deepdraw/solver/newton_increment.h>

namespace deepdraw
{
  namespace problem
  {
    using namespace dealii;

    // l2 norm of the displacement block of a vector of Newton unknowns.
    double
    displacement_norm(const SheetModel &model, const Vector<double> &vector);

    // The free displacement rows and the contact rows relative to the
    // model's force scale; whether the tool forces are met to
    // tool_force_tolerance (none asked if it is <= 0) at target_load.
    solver::ResidualMeasures
    measure_residuals(const SheetModel &model,
                      double            target_load,
                      double            tool_force_tolerance);

    // The out-of-balance forces of all equations in N (free displacement
    // rows, r F_sup, tool equations): the line search's merit.
    double
    out_of_balance_force(const SheetModel &model);

    // A correction's norm relative to the displacement so far with the
    // iterate x (D26).
    double
    correction_relative_to_displacement(const SheetModel     &model,
                                        const Vector<double> &x,
                                        double                correction_norm);
  } // namespace problem
} // namespace deepdraw

#endif
