#include <algorithm>
#include <cmath>
#include <deepdraw/solver/multiplier_condensation.h>
#include <stdexcept>

namespace deepdraw
{
  namespace solver
  {
    namespace
    {
      // A row of the condensed matrix summed from rows of the whole one:
      // a dense accumulator over the condensed columns, and the columns
      // touched, so that a contribution outside the condensed pattern is
      // detected instead of lost.
      class RowAccumulator
      {
      public:
        RowAccumulator(const std::vector<types::global_dof_index> &map,
                       const types::global_dof_index               n)
            : condensed_of(map)
            , values(n, 0.)
            , touched(n, false)
        {
        }

        // values += factor * row i of matrix (multiplier columns skipped:
        // they are what the combination eliminates).
        void
        add(const SparseMatrix<double>   &matrix,
            const types::global_dof_index i,
            const double                  factor)
        {
          if (factor == 0.)
            return;
          for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
          {
            const auto j = condensed_of[entry->column()];
            if (j == numbers::invalid_dof_index)
              continue;
            values[j] += factor * entry->value();
            if (!touched[j])
            {
              touched[j] = true;
              columns.push_back(j);
            }
          }
        }

        // Writes the sum into row ci of `target` and clears; false if a
        // nonzero lies outside the row's pattern.
        bool
        store(SparseMatrix<double> &target, const types::global_dof_index ci)
        {
          for (auto entry = target.begin(ci); entry != target.end(ci); ++entry)
          {
            const auto j   = entry->column();
            entry->value() = values[j];
            values[j]      = 0.;
          }
          bool fits = true;
          for (const auto j : columns)
          {
            fits       = fits && values[j] == 0.;
            values[j]  = 0.;
            touched[j] = false;
          }
          columns.clear();
          return fits;
        }

      private:
        const std::vector<types::global_dof_index> &condensed_of;
        std::vector<double>                         values;
        std::vector<bool>                           touched;
        std::vector<types::global_dof_index>        columns;
      };

      // Row i of matrix times x over the condensed columns.
      double
      row_times(const SparseMatrix<double>                 &matrix,
                const types::global_dof_index               i,
                const std::vector<types::global_dof_index> &condensed_of,
                const Vector<double>                       &x)
      {
        double sum = 0.;
        for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
        {
          const auto j = condensed_of[entry->column()];
          if (j != numbers::invalid_dof_index)
            sum += entry->value() * x[j];
        }
        return sum;
      }

      double
      max_abs(const FullMatrix<double> &m)
      {
        double largest = 0.;
        for (unsigned int i = 0; i < m.m(); ++i)
          for (unsigned int j = 0; j < m.n(); ++j)
            largest = std::max(largest, std::abs(m(i, j)));
        return largest;
      }

      // Inverts a (at most 3 x 3) in place; false if it is singular or
      // ill-conditioned: deal.II's gauss_jordan only asserts in debug mode,
      // so the product with the original is checked (A A^-1 = I to 1e-10).
      bool
      invert_checked(FullMatrix<double> &a)
      {
        const FullMatrix<double> original(a);
        a.gauss_jordan();
        FullMatrix<double> product(a.m(), a.m());
        original.mmult(product, a);
        for (unsigned int i = 0; i < a.m(); ++i)
          product(i, i) -= 1.;
        const double error = max_abs(product);
        return std::isfinite(error) && error <= 1e-10;
      }
    } // namespace


    void
    MultiplierCondensation::initialize(
      const SparsityPattern                      &pattern,
      const types::global_dof_index               n_displacements,
      const std::vector<MultiplierBlock>         &pair_blocks,
      const std::vector<types::global_dof_index> &tool_positions,
      const std::vector<bool>                    &constrained)
    {
      n_u                               = n_displacements;
      blocks                            = pair_blocks;
      tool_position_dofs                = tool_positions;
      is_constrained                    = constrained;
      const types::global_dof_index n   = pattern.n_rows();
      const types::global_dof_index n_c = n_u + tool_positions.size();
      AssertThrow(is_constrained.size() == n, ExcInternalError());

      condensed_of.assign(n, numbers::invalid_dof_index);
      for (types::global_dof_index i = 0; i < n_u; ++i)
        condensed_of[i] = i;
      for (unsigned int k = 0; k < tool_positions.size(); ++k)
        condensed_of[tool_positions[k]] = n_u + k;
      blocks_of_node.assign(n_u, {});
      for (unsigned int k = 0; k < blocks.size(); ++k)
        blocks_of_node[blocks[k].displacement[0]].push_back(k);
      local_blocks.assign(blocks.size(), LocalBlocks());

      // Displacement rows keep their pattern (the multiplier rows of a
      // pair couple only to its node and z, which the node's rows have);
      // the tool rows become dense (a tool's pairs bring their nodes'
      // rows), as LinearSolver borders them anyway.
      std::vector<unsigned int> row_lengths(n_c, n_c);
      for (types::global_dof_index i = 0; i < n_u; ++i)
        row_lengths[i] = pattern.row_length(i);
      condensed_pattern.reinit(n_c, n_c, row_lengths);
      std::vector<types::global_dof_index> columns;
      for (types::global_dof_index i = 0; i < n_c; ++i)
      {
        columns.clear();
        if (i < n_u)
        {
          for (auto entry = pattern.begin(i); entry != pattern.end(i); ++entry)
            if (condensed_of[entry->column()] != numbers::invalid_dof_index)
              columns.push_back(condensed_of[entry->column()]);
        }
        else
          for (types::global_dof_index j = 0; j < n_c; ++j)
            columns.push_back(j);
        std::sort(columns.begin(), columns.end());
        condensed_pattern.add_entries(i, columns.begin(), columns.end(), true);
      }
      condensed_pattern.compress();
      condensed_matrix.reinit(condensed_pattern);
      condensed_rhs.reinit(n_c);
    }


    bool
    MultiplierCondensation::read_blocks(const SparseMatrix<double> &matrix,
                                        const unsigned int          k,
                                        LocalBlocks                &local) const
    {
      const MultiplierBlock &block = blocks[k];
      local.free.clear();
      for (unsigned int c = 0; c < 3; ++c)
        if (!is_constrained[block.multiplier[c]]
            && !is_constrained[block.displacement[c]])
          local.free.push_back(c);
      const unsigned int m = local.free.size();
      FullMatrix<double> B(m, m), C(m, m);
      for (unsigned int a = 0; a < m; ++a)
        for (unsigned int b = 0; b < m; ++b)
        {
          B(a, b) = matrix.el(block.displacement[local.free[a]],
                              block.multiplier[local.free[b]]);
          C(a, b) = matrix.el(block.multiplier[local.free[a]],
                              block.multiplier[local.free[b]]);
        }
      local.coupled = m > 0 && max_abs(B) > 0.;
      local.X.reinit(m, m);
      local.Y.reinit(m, m);
      local.P_l.reinit(m, m);
      local.P_u.reinit(m, m);
      if (m == 0)
        return true;
      const double r = block.augmentation;
      if (!local.coupled)
      {
        // Open: the node rows hold no multiplier; C = I / r.
        for (unsigned int a = 0; a < m; ++a)
          local.X(a, a) = 1.;
        local.P_l = C;
        return invert_checked(local.P_l);
      }
      // The elimination needs B C = C B (Alart–Curnier: polynomials in D).
      FullMatrix<double> BC(m, m), CB(m, m);
      B.mmult(BC, C);
      C.mmult(CB, B);
      BC.add(-1., CB);
      if (max_abs(BC) > 1e-10 * max_abs(B) * std::max(max_abs(C), 1. / r))
        return false;
      local.X = C;
      local.X *= r;
      local.Y = B;
      local.Y *= -r;
      // E = r C - B (= I for the Alart–Curnier law), Eq. 4.2.
      FullMatrix<double> E(local.X);
      E.add(-1., B);
      if (!invert_checked(E))
        return false;
      local.P_l = E;
      local.P_l *= r;
      local.P_u = E;
      local.P_u *= -1.;
      return true;
    }


    bool
    MultiplierCondensation::condense(const SparseMatrix<double> &matrix,
                                     const Vector<double>       &rhs)
    {
      coupled_pairs = 0;
      for (unsigned int k = 0; k < blocks.size(); ++k)
      {
        // False for blocks without the structure of Eq. 4.1 or a singular
        // E or C.
        if (!read_blocks(matrix, k, local_blocks[k]))
          return false;
        coupled_pairs += local_blocks[k].coupled;
      }

      const types::global_dof_index n_c = condensed_pattern.n_rows();
      RowAccumulator                row(condensed_of, n_c);
      condensed_matrix = 0.;
      condensed_rhs    = 0.;
      std::vector<bool> done(n_u, false);
      // Nodes with a coupled pair: the eliminating combination on its free
      // components; every other displacement row is copied.
      for (types::global_dof_index node = 0; node < n_u; ++node)
      {
        const std::vector<unsigned int> &node_blocks = blocks_of_node[node];
        const auto coupled = std::count_if(node_blocks.begin(),
                                           node_blocks.end(),
                                           [&](const unsigned int k)
                                           { return local_blocks[k].coupled; });
        if (coupled > 1)
          return false;
        for (const unsigned int k : node_blocks)
        {
          const LocalBlocks &local = local_blocks[k];
          if (!local.coupled)
            continue;
          const MultiplierBlock &block = blocks[k];
          for (unsigned int a = 0; a < local.free.size(); ++a)
          {
            double b = 0.;
            for (unsigned int c = 0; c < local.free.size(); ++c)
            {
              const auto u_row = block.displacement[local.free[c]];
              const auto l_row = block.multiplier[local.free[c]];
              row.add(matrix, u_row, local.X(a, c));
              row.add(matrix, l_row, local.Y(a, c));
              b += local.X(a, c) * rhs[u_row] + local.Y(a, c) * rhs[l_row];
            }
            const auto i = block.displacement[local.free[a]];
            if (!row.store(condensed_matrix, i))
              return false;
            condensed_rhs[i] = b;
            done[i]          = true;
          }
        }
      }
      for (types::global_dof_index i = 0; i < n_u; ++i)
        if (!done[i])
        {
          // A multiplier column left here would be lost.
          for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
            if (condensed_of[entry->column()] == numbers::invalid_dof_index
                && entry->value() != 0.)
              return false;
          row.add(matrix, i, 1.);
          if (!row.store(condensed_matrix, i))
            return false;
          condensed_rhs[i] = rhs[i];
        }

      // Tool rows: dlambda of every pair they hold substituted (Eq. 4.2).
      for (unsigned int t = 0; t < tool_position_dofs.size(); ++t)
      {
        const auto z = tool_position_dofs[t];
        row.add(matrix, z, 1.);
        double b = rhs[z];
        for (unsigned int k = 0; k < blocks.size(); ++k)
        {
          const LocalBlocks     &local = local_blocks[k];
          const MultiplierBlock &block = blocks[k];
          for (unsigned int a = 0; a < local.free.size(); ++a)
          {
            const double g = matrix.el(z, block.multiplier[local.free[a]]);
            if (g == 0.)
              continue;
            for (unsigned int c = 0; c < local.free.size(); ++c)
            {
              const auto u_row = block.displacement[local.free[c]];
              const auto l_row = block.multiplier[local.free[c]];
              row.add(matrix, l_row, -g * local.P_l(a, c));
              row.add(matrix, u_row, -g * local.P_u(a, c));
              b -= g
                   * (local.P_l(a, c) * rhs[l_row]
                      + local.P_u(a, c) * rhs[u_row]);
            }
          }
        }
        if (!row.store(condensed_matrix, n_u + t))
          return false;
        condensed_rhs[n_u + t] = b;
      }
      return true;
    }


    const SparseMatrix<double> &
    MultiplierCondensation::matrix() const
    {
      return condensed_matrix;
    }


    const Vector<double> &
    MultiplierCondensation::rhs() const
    {
      return condensed_rhs;
    }


    std::vector<types::global_dof_index>
    MultiplierCondensation::condensed_tool_positions() const
    {
      std::vector<types::global_dof_index> positions;
      for (unsigned int t = 0; t < tool_position_dofs.size(); ++t)
        positions.push_back(n_u + t);
      return positions;
    }


    void
    MultiplierCondensation::expand(const SparseMatrix<double> &matrix,
                                   const Vector<double>       &rhs,
                                   const Vector<double> &condensed_solution,
                                   Vector<double>       &solution) const
    {
      solution.reinit(matrix.m());
      for (types::global_dof_index i = 0; i < matrix.m(); ++i)
        if (condensed_of[i] != numbers::invalid_dof_index)
          solution[i] = condensed_solution[condensed_of[i]];
      for (unsigned int k = 0; k < blocks.size(); ++k)
      {
        const LocalBlocks     &local = local_blocks[k];
        const MultiplierBlock &block = blocks[k];
        for (unsigned int c = 0; c < 3; ++c)
          if (is_constrained[block.multiplier[c]])
            solution[block.multiplier[c]]
              = rhs[block.multiplier[c]]
                / matrix.diag_element(block.multiplier[c]);
        const unsigned int  m = local.free.size();
        std::vector<double> s_l(m), s_u(m);
        for (unsigned int c = 0; c < m; ++c)
        {
          const auto l_row = block.multiplier[local.free[c]];
          const auto u_row = block.displacement[local.free[c]];
          s_l[c]           = rhs[l_row]
                   - row_times(matrix, l_row, condensed_of, condensed_solution);
          s_u[c]
            = local.coupled
                ? rhs[u_row]
                    - row_times(matrix, u_row, condensed_of, condensed_solution)
                : 0.;
        }
        for (unsigned int a = 0; a < m; ++a)
        {
          double value = 0.;
          for (unsigned int c = 0; c < m; ++c)
            value += local.P_l(a, c) * s_l[c] + local.P_u(a, c) * s_u[c];
          solution[block.multiplier[local.free[a]]] = value;
        }
      }
    }


    unsigned int
    MultiplierCondensation::n_coupled_pairs() const
    {
      return coupled_pairs;
    }
  } // namespace solver
} // namespace deepdraw
