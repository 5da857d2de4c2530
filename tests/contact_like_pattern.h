// The pattern of a contact-like Newton matrix for the linear-solver tests:
// n displacement-like unknowns in a chain, a multiplier per node coupled to
// it, and one bordered unknown (the holder position) coupled to every
// multiplier; 2 n + 1 unknowns.
#ifndef deepdraw_tests_contact_like_pattern_h
#define deepdraw_tests_contact_like_pattern_h

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <vector>

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

  // Values on that pattern: the chain's stiffness, the closed pairs'
  // couplings (closed[i] for node i; an open pair's multiplier has only
  // its diagonal), the bordered unknown coupled to the closed multipliers;
  // node 0 is a constrained displacement (diagonal only) when its pair is
  // open.
  inline void
  fill_contact_like_matrix(dealii::SparseMatrix<double> &A,
                           const std::vector<bool>      &closed)
  {
    const unsigned int n = closed.size();
    A                    = 0.;
    for (unsigned int i = 0; i < n; ++i)
    {
      A.set(i, i, 2. + 0.1 * i);
      if (i > 1)
        A.set(i, i - 1, -1.);
      if (i > 0 && i + 1 < n)
        A.set(i, i + 1, -1.);
      const double coupling = closed[i] ? 1. + 0.01 * i : 0.;
      A.set(i, n + i, -coupling);
      A.set(n + i, i, coupling);
      A.set(n + i, n + i, closed[i] ? 0.3 * (i % 2) : 1e-3);
      A.set(n + i, 2 * n, closed[i] ? 0.5 : 0.);
      A.set(2 * n, n + i, closed[i] ? 1. : 0.);
    }
    A.set(2 * n, 2 * n, 1.);
  }
} // namespace deepdraw_test

#endif
