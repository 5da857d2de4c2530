// Which rows of the Newton system a rank holds and which it owns when the
// ranks split the matrix by rows (doc/architecture.md, "Parallel runs",
// D214). A rank holds a row whose entries it stores; it owns the rows whose
// values it alone completes and hands to the factorisation. With one rank
// every row is held and owned.
#ifndef deepdraw_linear_algebra_row_partition_h
#define deepdraw_linear_algebra_row_partition_h

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deepdraw/solver/multiplier_condensation.h>
#include <vector>

namespace deepdraw
{
  namespace linear_algebra
  {
    using namespace dealii;

    class RowPartition
    {
    public:
      // The rows of n_unknowns unknowns: the displacements of dof_handler
      // (coupled through the cells and `constraints`), the contact pairs'
      // multipliers (`blocks`) and the rest (the tool positions), on this
      // rank of the run. Every rank constructs it with the same arguments;
      // it communicates nothing.
      RowPartition(const DoFHandler<3>                        &dof_handler,
                   const AffineConstraints<double>            &constraints,
                   types::global_dof_index                     n_unknowns,
                   const std::vector<solver::MultiplierBlock> &blocks);

      bool
      holds(const types::global_dof_index row) const
      {
        return held[row];
      }
      bool
      owns(const types::global_dof_index row) const
      {
        return owned[row];
      }
      const std::vector<bool> &
      owned_rows() const
      {
        return owned;
      }
      // The held rows, for a sparsity pattern of those rows only.
      const IndexSet &
      held_rows() const
      {
        return held_set;
      }

      // Displacement rows this rank holds and rank r owns (to_owner[r]), and
      // those rank r holds and this rank owns (from_rank[r]), ascending:
      // after the element loop each sends the cells' sums of the first to
      // their owners, who add them (D214).
      const std::vector<std::vector<types::global_dof_index>> &
      rows_to_send() const
      {
        return to_owner;
      }
      // Collective at its first call, which also checks that every rank
      // divided the cells alike (std::runtime_error if not).
      const std::vector<std::vector<types::global_dof_index>> &
      rows_to_receive();

    private:
      std::vector<bool>                                 held, owned;
      IndexSet                                          held_set;
      std::vector<std::vector<types::global_dof_index>> to_owner, from_rank;
      unsigned long long owners_fingerprint = 14695981039346656037ULL;
    };
  } // namespace linear_algebra
} // namespace deepdraw

#endif
