#include <algorithm>
#include <atomic>
#include <cmath>
#include <deal.II/base/parallel.h>
#include <deepdraw/parallel/ranks.h>
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

      using Block3 = std::array<std::array<double, 3>, 3>;

      double
      max_abs(const Block3 &a, const unsigned int m)
      {
        double largest = 0.;
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < m; ++j)
            largest = std::max(largest, std::abs(a[i][j]));
        return largest;
      }

      Block3
      product(const Block3 &a, const Block3 &b, const unsigned int m)
      {
        Block3 c{};
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < m; ++j)
            for (unsigned int k = 0; k < m; ++k)
              c[i][j] += a[i][k] * b[k][j];
        return c;
      }

      // Inverts the leading m x m (m <= 3) of a in place by Gauss–Jordan
      // with partial pivoting; false if it is singular or ill-conditioned:
      // the product with the original is checked (A A^-1 = I to 1e-10).
      bool
      invert_checked(Block3 &a, const unsigned int m)
      {
        const Block3 original = a;
        Block3       inverse{};
        for (unsigned int i = 0; i < m; ++i)
          inverse[i][i] = 1.;
        for (unsigned int c = 0; c < m; ++c)
        {
          unsigned int pivot = c;
          for (unsigned int r = c + 1; r < m; ++r)
            if (std::abs(a[r][c]) > std::abs(a[pivot][c]))
              pivot = r;
          if (a[pivot][c] == 0.)
            return false;
          std::swap(a[c], a[pivot]);
          std::swap(inverse[c], inverse[pivot]);
          const double scale = 1. / a[c][c];
          for (unsigned int j = 0; j < m; ++j)
          {
            a[c][j] *= scale;
            inverse[c][j] *= scale;
          }
          for (unsigned int r = 0; r < m; ++r)
            if (r != c && a[r][c] != 0.)
            {
              const double factor = a[r][c];
              for (unsigned int j = 0; j < m; ++j)
              {
                a[r][j] -= factor * a[c][j];
                inverse[r][j] -= factor * inverse[c][j];
              }
            }
        }
        a            = inverse;
        Block3 check = product(original, a, m);
        for (unsigned int i = 0; i < m; ++i)
          check[i][i] -= 1.;
        const double error = max_abs(check, m);
        return std::isfinite(error) && error <= 1e-10;
      }

      double
      entry_at(const SparseMatrix<double> &matrix, const std::size_t position)
      {
        return position == SparsityPattern::invalid_entry
                 ? 0.
                 : SparseMatrix<double>::const_iterator(&matrix, position)
                     ->value();
      }
    } // namespace


    void
    MultiplierCondensation::initialize(
      const SparsityPattern                      &pattern,
      const types::global_dof_index               n_displacements,
      const std::vector<MultiplierBlock>         &pair_blocks,
      const std::vector<types::global_dof_index> &tool_positions,
      const std::vector<bool>                    &constrained,
      const std::vector<bool>                    &owned_rows)
    {
      owned                             = owned_rows;
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
      positions.assign(blocks.size(), BlockPositions());
      for (unsigned int k = 0; k < blocks.size(); ++k)
      {
        const MultiplierBlock &block = blocks[k];
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
          {
            positions[k].B[a][b]
              = pattern(block.displacement[a], block.multiplier[b]);
            positions[k].C[a][b]
              = pattern(block.multiplier[a], block.multiplier[b]);
          }
        for (const auto z : tool_positions)
        {
          std::array<std::size_t, 3> row;
          for (unsigned int a = 0; a < 3; ++a)
            row[a] = pattern(z, block.multiplier[a]);
          positions[k].tool_row.push_back(row);
        }
      }

      // Displacement rows keep their pattern (the multiplier rows of a
      // pair couple only to its node and z, which the node's rows have);
      // the tool rows become dense (a tool's pairs bring their nodes'
      // rows), as LinearSolver borders them anyway.
      // Under mpirun a rank's rows of other ranks keep their diagonal.
      std::vector<unsigned int> row_lengths(n_c, n_c);
      for (types::global_dof_index i = 0; i < n_u; ++i)
        row_lengths[i] = owns(i) ? pattern.row_length(i) : 1;
      condensed_pattern.reinit(n_c, n_c, row_lengths);
      std::vector<types::global_dof_index> columns;
      for (types::global_dof_index i = 0; i < n_c; ++i)
      {
        columns.clear();
        if (i < n_u && !owns(i))
          columns.push_back(i);
        else if (i < n_u)
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
      local.n_free                 = 0;
      for (unsigned int c = 0; c < 3; ++c)
        if (!is_constrained[block.multiplier[c]]
            && !is_constrained[block.displacement[c]])
          local.free[local.n_free++] = c;
      const unsigned int m = local.n_free;
      Block3             B{}, C{};
      for (unsigned int a = 0; a < m; ++a)
        for (unsigned int b = 0; b < m; ++b)
        {
          B[a][b]
            = entry_at(matrix, positions[k].B[local.free[a]][local.free[b]]);
          C[a][b]
            = entry_at(matrix, positions[k].C[local.free[a]][local.free[b]]);
        }
      local.coupled = m > 0 && max_abs(B, m) > 0.;
      for (Block3 *block_matrix : {&local.X, &local.Y, &local.P_l, &local.P_u})
        *block_matrix = Block3{};
      if (m == 0)
        return true;
      const double r = block.augmentation;
      if (!local.coupled)
      {
        // Open: the node rows hold no multiplier; C = I / r.
        for (unsigned int a = 0; a < m; ++a)
          local.X[a][a] = 1.;
        local.P_l = C;
        return invert_checked(local.P_l, m);
      }
      // The elimination needs B C = C B (Alart–Curnier: polynomials in D).
      Block3       commutator = product(B, C, m);
      const Block3 CB         = product(C, B, m);
      for (unsigned int a = 0; a < m; ++a)
        for (unsigned int b = 0; b < m; ++b)
          commutator[a][b] -= CB[a][b];
      if (max_abs(commutator, m)
          > 1e-10 * max_abs(B, m) * std::max(max_abs(C, m), 1. / r))
        return false;
      // E = r C - B (= I for the Alart–Curnier law), Eq. 4.2.
      Block3 E{};
      for (unsigned int a = 0; a < m; ++a)
        for (unsigned int b = 0; b < m; ++b)
        {
          local.X[a][b] = r * C[a][b];
          local.Y[a][b] = -r * B[a][b];
          E[a][b]       = r * C[a][b] - B[a][b];
        }
      if (!invert_checked(E, m))
        return false;
      for (unsigned int a = 0; a < m; ++a)
        for (unsigned int b = 0; b < m; ++b)
        {
          local.P_l[a][b] = r * E[a][b];
          local.P_u[a][b] = -E[a][b];
        }
      return true;
    }


    bool
    MultiplierCondensation::copy_row(const SparseMatrix<double>   &matrix,
                                     const types::global_dof_index i)
    {
      // Both rows hold the diagonal first, then ascending columns, and
      // condensed_of is monotone (displacements, then tool positions in
      // order): the condensed row is the whole row without the multiplier
      // columns, entry by entry.
      auto target = condensed_matrix.begin(i);
      for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
      {
        const auto j = condensed_of[entry->column()];
        if (j == numbers::invalid_dof_index)
        {
          // A multiplier column left here would be lost.
          if (entry->value() != 0.)
            return false;
          continue;
        }
        AssertThrow(target != condensed_matrix.end(i) && target->column() == j,
                    ExcInternalError());
        target->value() = entry->value();
        ++target;
      }
      AssertThrow(target == condensed_matrix.end(i), ExcInternalError());
      return true;
    }


    std::vector<bool>
    MultiplierCondensation::owned_condensed_rows() const
    {
      if (owned.empty())
        return {};
      std::vector<bool> rows(owned.begin(), owned.begin() + n_u);
      rows.resize(n_u + tool_position_dofs.size(), parallel::is_root());
      return rows;
    }


    bool
    MultiplierCondensation::condense(const SparseMatrix<double> &matrix,
                                     const Vector<double>       &rhs)
    {
      bool condensed = condense_owned(matrix, rhs);
      if (owned.empty())
        return condensed;
      // Every rank takes the same path; each added its own pairs to the
      // tool rows (D214).
      condensed = parallel::maximum(condensed ? 0 : 1) == 0;
      coupled_pairs
        = static_cast<unsigned int>(parallel::sum(coupled_pairs + 0ULL));
      if (!condensed)
        return false;
      for (unsigned int t = 0; t < tool_position_dofs.size(); ++t)
      {
        const auto row = n_u + t;
        // A row's values lie together; the diagonal (0, 0) is the first.
        double *values = const_cast<double *>(&condensed_matrix(0, 0));
        parallel::sum(values + condensed_pattern.begin(row)->global_index(),
                      condensed_pattern.row_length(row));
      }
      // Each rank wrote the right-hand side of its own rows (the others
      // stay zero), and its part of the tool rows'.
      parallel::sum(condensed_rhs.begin(), condensed_rhs.size());
      return true;
    }


    bool
    MultiplierCondensation::condense_owned(const SparseMatrix<double> &matrix,
                                           const Vector<double>       &rhs)
    {
      coupled_pairs = 0;
      // The right-hand side of the last solve was summed over the ranks.
      if (!owned.empty())
        condensed_rhs = 0.;
      for (unsigned int k = 0; k < blocks.size(); ++k)
      {
        local_blocks[k] = LocalBlocks();
        if (!owns(blocks[k].displacement[0]))
          continue;
        // False for blocks without the structure of Eq. 4.1 or a singular
        // E or C.
        if (!read_blocks(matrix, k, local_blocks[k]))
          return false;
        coupled_pairs += local_blocks[k].coupled;
      }

      const types::global_dof_index n_c = condensed_pattern.n_rows();
      RowAccumulator                row(condensed_of, n_c);
      // Every row is written below: no zeroing.
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
          for (unsigned int a = 0; a < local.n_free; ++a)
          {
            double b = 0.;
            for (unsigned int c = 0; c < local.n_free; ++c)
            {
              const auto   u_row = block.displacement[local.free[c]];
              const auto   l_row = block.multiplier[local.free[c]];
              const double x     = local.X[a][c];
              const double y     = local.Y[a][c];
              row.add(matrix, u_row, x);
              row.add(matrix, l_row, y);
              b += x * rhs[u_row] + y * rhs[l_row];
            }
            const auto i = block.displacement[local.free[a]];
            if (!row.store(condensed_matrix, i))
              return false;
            condensed_rhs[i] = b;
            done[i]          = true;
          }
        }
      }
      // The copied rows are independent: both cores (D98).
      std::atomic<bool> copied{true};
      dealii::parallel::apply_to_subranges(
        types::global_dof_index(0),
        n_u,
        [&](const types::global_dof_index begin,
            const types::global_dof_index end)
        {
          for (types::global_dof_index i = begin; i < end; ++i)
            if (!done[i] && owns(i))
            {
              if (!copy_row(matrix, i))
                copied = false;
              condensed_rhs[i] = rhs[i];
            }
        },
        2048);
      if (!copied)
        return false;

      // Tool rows: dlambda of every pair they hold substituted (Eq. 4.2);
      // under mpirun each rank its own pairs', rank 0 the row itself.
      const bool with_tool_row = owned.empty() || parallel::is_root();
      for (unsigned int t = 0; t < tool_position_dofs.size(); ++t)
      {
        const auto z = tool_position_dofs[t];
        if (with_tool_row)
          row.add(matrix, z, 1.);
        double b = with_tool_row ? rhs[z] : 0.;
        for (unsigned int k = 0; k < blocks.size(); ++k)
        {
          const LocalBlocks     &local = local_blocks[k];
          const MultiplierBlock &block = blocks[k];
          for (unsigned int a = 0; a < local.n_free; ++a)
          {
            const double g
              = entry_at(matrix, positions[k].tool_row[t][local.free[a]]);
            if (g == 0.)
              continue;
            for (unsigned int c = 0; c < local.n_free; ++c)
            {
              const auto   u_row = block.displacement[local.free[c]];
              const auto   l_row = block.multiplier[local.free[c]];
              const double p_l   = local.P_l[a][c];
              const double p_u   = local.P_u[a][c];
              row.add(matrix, l_row, -g * p_l);
              row.add(matrix, u_row, -g * p_u);
              b -= g * (p_l * rhs[l_row] + p_u * rhs[u_row]);
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
      for (unsigned int k = 0; k < blocks.size(); ++k)
      {
        const LocalBlocks     &local = local_blocks[k];
        const MultiplierBlock &block = blocks[k];
        if (!owns(block.displacement[0]))
          continue;
        for (unsigned int c = 0; c < 3; ++c)
          if (is_constrained[block.multiplier[c]])
            solution[block.multiplier[c]]
              = rhs[block.multiplier[c]]
                / matrix.diag_element(block.multiplier[c]);
        const unsigned int    m = local.n_free;
        std::array<double, 3> s_l{}, s_u{};
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
            value += local.P_l[a][c] * s_l[c] + local.P_u[a][c] * s_u[c];
          solution[block.multiplier[local.free[a]]] = value;
        }
      }
      // Each rank solved for its own pairs' multipliers (D214).
      if (!owned.empty())
        parallel::sum(solution.begin(), solution.size());
      for (types::global_dof_index i = 0; i < matrix.m(); ++i)
        if (condensed_of[i] != numbers::invalid_dof_index)
          solution[i] = condensed_solution[condensed_of[i]];
    }


    unsigned int
    MultiplierCondensation::n_coupled_pairs() const
    {
      return coupled_pairs;
    }


    std::vector<std::array<types::global_dof_index, 3>>
    MultiplierCondensation::coupled_nodes() const
    {
      std::vector<std::array<types::global_dof_index, 3>> nodes;
      nodes.reserve(coupled_pairs);
      for (unsigned int k = 0; k < local_blocks.size(); ++k)
        if (local_blocks[k].coupled)
          nodes.push_back(blocks[k].displacement);
      return nodes;
    }
  } // namespace solver
} // namespace deepdraw
