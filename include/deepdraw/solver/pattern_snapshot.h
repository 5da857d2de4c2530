// A copy of a sparsity pattern's structure, to tell whether a pattern
// handed to a factorisation is still the one it analysed: a pattern object
// may be rebuilt in place, so its address says nothing (D27, D96).
#ifndef deepdraw_solver_pattern_snapshot_h
#define deepdraw_solver_pattern_snapshot_h

#include <deal.II/lac/sparsity_pattern.h>
#include <vector>

namespace deepdraw
{
  namespace solver
  {
    using namespace dealii;

    class PatternSnapshot
    {
    public:
      void
      take(const SparsityPattern &pattern);
      // Same rows and the same columns in each (cheap next to a
      // factorisation); false before the first take().
      bool
      matches(const SparsityPattern &pattern) const;

    private:
      std::vector<std::size_t>             row_start;
      std::vector<types::global_dof_index> columns;
    };
  } // namespace solver
} // namespace deepdraw

#endif
