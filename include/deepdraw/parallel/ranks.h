// The MPI ranks of a run (doc/architecture.md, "Parallel runs", D199).
// Every rank holds the whole mesh and the Newton vectors and takes every
// decision itself; what is split is the work: each rank evaluates the
// elements of its cells (parallel/cell_partition.h), keeping their
// material state (parallel/owned_cells.h), and completes the Newton rows
// it owns, and MUMPS factorises across all ranks. So that the ranks
// take the same decisions, every sum over ranks gives the same bits on every
// rank (reduced on rank 0, then broadcast). With one rank every function here
// returns at once and changes nothing.
#ifndef deepdraw_parallel_ranks_h
#define deepdraw_parallel_ranks_h

#include <cstddef>
#include <type_traits>
#include <vector>

namespace deepdraw
{
  namespace parallel
  {
    // The size of and this process's rank in MPI_COMM_WORLD (1 and 0 where
    // MPI is not initialised, as in the unit tests).
    unsigned int
    n_ranks();
    unsigned int
    this_rank();
    bool
    is_root();

    // How many ranks of the run share this process's machine (its memory):
    // MPI_COMM_TYPE_SHARED. Counted at the first call, which must be one
    // that every rank makes (start_ranks makes it); 1 without MPI.
    unsigned int
    ranks_on_this_machine();

    // values[i] summed over the ranks, the same bits on every rank.
    void
    sum(double *values, std::size_t n);
    unsigned long long
    sum(unsigned long long value);
    int
    maximum(int value);

    // Each rank sends to_rank[s] to rank s and receives what rank s sent
    // it in from_rank[s] (its own entry copied): the rows of the Newton
    // matrix that a rank's cells added to and another rank owns (D214).
    void
    exchange(const std::vector<std::vector<double>> &to_rank,
             std::vector<std::vector<double>>       &from_rank);
    void
    exchange(const std::vector<std::vector<unsigned long long>> &to_rank,
             std::vector<std::vector<unsigned long long>>       &from_rank);

    // Returns once every rank has called it.
    void
    barrier();

    // Every rank receives rank root's bytes.
    void
    broadcast(void *data, std::size_t bytes, unsigned int root = 0);

    // Rank `from` sends `bytes` bytes of `sent` to rank 0, which receives
    // them in `received`; the other ranks do nothing (a checkpoint's
    // state, D217).
    void
    send_to_root(const void  *sent,
                 void        *received,
                 std::size_t  bytes,
                 unsigned int from);

    // Each rank sends sent_counts[s] records of bytes_per_record bytes,
    // consecutive in `sent` by destination, to rank s and receives
    // receive_counts[s] records from rank s, consecutive in `received` by
    // source (a refinement's cell records to the cells' new ranks, D220).
    void
    exchange_records(const void                     *sent,
                     const std::vector<std::size_t> &sent_counts,
                     void                           *received,
                     const std::vector<std::size_t> &receive_counts,
                     std::size_t                     bytes_per_record);

    // Records computed by their owners, sent to every rank in place: data
    // holds bytes_per_owner bytes for each i of owners, computed by rank
    // owners[i] (a cell's trial state, D215).
    void
    gather_from_owners(void                            *data,
                       std::size_t                      bytes_per_owner,
                       const std::vector<unsigned int> &owners);

    // The same for a vector of items, items.size() / owners.size() items
    // for each owner; nothing with one rank or no owners.
    template <typename T>
    void
    gather_from_owners(std::vector<T>                  &items,
                       const std::vector<unsigned int> &owners)
    {
      static_assert(std::is_trivially_copyable<T>::value,
                    "records are sent as bytes");
      if (n_ranks() == 1 || items.empty() || owners.empty())
        return;
      gather_from_owners(items.data(),
                         sizeof(T) * (items.size() / owners.size()),
                         owners);
    }
  } // namespace parallel
} // namespace deepdraw

#endif
