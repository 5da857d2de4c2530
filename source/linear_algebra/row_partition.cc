#include <deepdraw/linear_algebra/row_partition.h>
#include <deepdraw/parallel/ranks.h>
#include <stdexcept>

namespace deepdraw
{
  namespace linear_algebra
  {
    RowPartition::RowPartition(
      const DoFHandler<3>                        &dof_handler,
      const AffineConstraints<double>            &constraints,
      const types::global_dof_index               n,
      const std::vector<solver::MultiplierBlock> &blocks)
        : held(n, false)
        , owned(n, false)
        , held_set(n)
    {
      const unsigned int n_ranks = parallel::n_ranks();
      const unsigned int me      = parallel::this_rank();
      // A displacement row is owned by the rank of the first cell that has
      // it (the cells' subdomain ids, D215), and held by every rank with a
      // cell that has it.
      const types::global_dof_index n_u = dof_handler.n_dofs();
      std::vector<unsigned int>     owner(n, numbers::invalid_unsigned_int);
      std::vector<types::global_dof_index> dofs(
        dof_handler.get_fe().n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int rank = cell->subdomain_id();
        cell->get_dof_indices(dofs);
        for (const auto dof : dofs)
        {
          if (owner[dof] == numbers::invalid_unsigned_int)
            owner[dof] = rank;
          if (rank == me)
            held[dof] = true;
        }
      }

      // A pair's rows (its node's, its multipliers', the tool's) are added
      // on every rank alike after the element loop (D199): a rank adds
      // those of the pairs whose node it holds. A pair at a constrained
      // node is held everywhere, so that every rank adds it through the
      // constraints with the matrix (the right-hand side then takes the
      // inhomogeneities as on one rank).
      for (const auto &block : blocks)
        for (const auto dof : block.displacement)
          if (constraints.is_constrained(dof))
            for (const auto node_dof : block.displacement)
              held[node_dof] = true;
      // The masters of a held constrained row receive its entries.
      for (types::global_dof_index dof = 0; dof < n_u; ++dof)
        if (held[dof] && constraints.is_constrained(dof))
          if (const auto *entries = constraints.get_constraint_entries(dof))
            for (const auto &[master, weight] : *entries)
              held[master] = true;
      for (const auto &block : blocks)
        for (unsigned int c = 0; c < 3; ++c)
        {
          owner[block.multiplier[c]] = owner[block.displacement[0]];
          held[block.multiplier[c]]  = held[block.displacement[0]];
        }
      // Every other unknown (the tool positions) is held by all, owned by
      // rank 0: its row sums the pairs of a whole tool.
      for (types::global_dof_index i = n_u; i < n; ++i)
        if (owner[i] == numbers::invalid_unsigned_int)
        {
          held[i]  = true;
          owner[i] = 0;
        }

      for (types::global_dof_index i = 0; i < n; ++i)
      {
        owned[i] = owner[i] == me;
        held[i]  = held[i] || owned[i];
        if (held[i])
          held_set.add_index(i);
      }
      held_set.compress();
      // FNV-1a of the owners, compared across the ranks at the first
      // exchange: every rank partitions the cells itself (D215).
      for (const unsigned int rank : owner)
        owners_fingerprint = (owners_fingerprint ^ rank) * 1099511628211ULL;

      // Only cells add before the exchange: displacement rows.
      to_owner.assign(n_ranks, {});
      for (types::global_dof_index i = 0; i < n_u; ++i)
        if (held[i] && !owned[i])
          to_owner[owner[i]].push_back(i);
    }


    const std::vector<std::vector<types::global_dof_index>> &
    RowPartition::rows_to_receive()
    {
      // Told by the senders at the first exchange: a collective call, which
      // rank 0's commands alone (--check) never make (D199).
      if (from_rank.empty())
      {
        unsigned long long root_fingerprint = owners_fingerprint;
        parallel::broadcast(&root_fingerprint, sizeof(root_fingerprint));
        if (parallel::maximum(root_fingerprint != owners_fingerprint) != 0)
          throw std::runtime_error(
            "the ranks divided the cells differently (METIS gave another "
            "partition on some rank); run on one rank or report the MPI "
            "set-up");
        std::vector<std::vector<unsigned long long>> sent(to_owner.size()),
          received;
        for (unsigned int r = 0; r < to_owner.size(); ++r)
          sent[r].assign(to_owner[r].begin(), to_owner[r].end());
        parallel::exchange(sent, received);
        from_rank.assign(received.size(), {});
        for (unsigned int r = 0; r < received.size(); ++r)
          from_rank[r].assign(received[r].begin(), received[r].end());
      }
      return from_rank;
    }
  } // namespace linear_algebra
} // namespace deepdraw
