// The pattern of a contact-like Newton matrix for the linear-solver tests:
// n displacement-like unknowns in a chain, a multiplier per node coupled to
// it, and one bordered unknown (the holder position) coupled to every
// multiplier; 2 n + 1 unknowns.
#ifndef deepdraw_tests_contact_like_pattern_h
#define deepdraw_tests_contact_like_pattern_h

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>

namespace deepdraw_test
{
  inline void
  make_contact_like_pattern(const unsigned int       n,
                            dealii::SparsityPattern &pattern)
  {
    dealii::DynamicSparsityPattern dsp(2 * n + 1, 2 * n + 1);
    for (unsigned int i = 0; i < n; ++i)
    {
      for (const unsigned int j : {i, n + i})
      {
        dsp.add(i, j);
        dsp.add(j, i);
      }
      if (i > 0)
        dsp.add(i, i - 1);
      if (i + 1 < n)
        dsp.add(i, i + 1);
      dsp.add(n + i, n + i);
      dsp.add(n + i, 2 * n);
      dsp.add(2 * n, n + i);
    }
    dsp.add(2 * n, 2 * n);
    pattern.copy_from(dsp);
  }
} // namespace deepdraw_test

#endif
