// The Newton matrix as the element assembly and the contact coupling see it
// (doc/architecture.md, "Linear algebra"): they add cell and pair matrices
// through it and never learn how it is stored, so that a distributed
// matrix can stand beside the serial one (D100).
#ifndef deepdraw_linear_algebra_system_matrix_h
#define deepdraw_linear_algebra_system_matrix_h

#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <vector>

namespace deepdraw
{
  namespace linear_algebra
  {
    using namespace dealii;

    // The Newton vectors [du | lambda | z]: every process holds every
    // entry, so that the Newton iteration, the contact search and the
    // outputs index them by global number (D100).
    using Vector = dealii::Vector<double>;

    class SystemMatrix
    {
    public:
      virtual ~SystemMatrix() = default;

      // The matrix of a cell none of whose dofs is constrained, in the
      // order of the cell's dofs (the assembly's fast path, D99).
      virtual void
      add_cell_matrix(unsigned int              active_cell_index,
                      const FullMatrix<double> &cell_matrix)
        = 0;

      // A local matrix and right-hand side through the constraints, as
      // AffineConstraints::distribute_local_to_global adds them.
      virtual void
      add_local(const AffineConstraints<double>            &constraints,
                const FullMatrix<double>                   &local_matrix,
                const Vector                               &local_rhs,
                const std::vector<types::global_dof_index> &dofs,
                Vector                                     &rhs)
        = 0;

      // Each rank added its own cells (D199): each row's entries summed
      // over the ranks into the rank that owns the row (D214). Nothing to
      // do on one rank. The contact terms follow on every rank alike.
      virtual void
      sum_over_ranks()
        = 0;

      // One entry, which must be in the pattern.
      virtual void
      add(types::global_dof_index row,
          types::global_dof_index column,
          double                  value)
        = 0;
    };
  } // namespace linear_algebra
} // namespace deepdraw

#endif
