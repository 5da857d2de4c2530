#include <deepdraw/solver/pattern_snapshot.h>

namespace deepdraw
{
  namespace solver
  {
    void
    PatternSnapshot::take(const SparsityPattern &pattern)
    {
      row_start.assign(1, 0);
      columns.clear();
      columns.reserve(pattern.n_nonzero_elements());
      for (types::global_dof_index i = 0; i < pattern.n_rows(); ++i)
      {
        for (auto entry = pattern.begin(i); entry != pattern.end(i); ++entry)
          columns.push_back(entry->column());
        row_start.push_back(columns.size());
      }
    }


    bool
    PatternSnapshot::matches(const SparsityPattern &pattern) const
    {
      if (row_start.empty() || pattern.n_rows() + 1 != row_start.size()
          || pattern.n_nonzero_elements() != columns.size())
        return false;
      std::size_t k = 0;
      for (types::global_dof_index i = 0; i < pattern.n_rows(); ++i)
        for (auto entry = pattern.begin(i); entry != pattern.end(i);
             ++entry, ++k)
          if (columns[k] != entry->column())
            return false;
      return true;
    }
  } // namespace solver
} // namespace deepdraw
