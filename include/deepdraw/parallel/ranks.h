// The MPI ranks of a run (doc/architecture.md, "Parallel runs", D199).
// Every rank holds the whole model (mesh, state, Newton vectors) and takes
// every decision itself; what is split is the work: each rank evaluates
// the elements of its share of the cells, and MUMPS factorises across all
// ranks. So that the ranks take the same decisions, every sum over ranks
// gives the same bits on every rank (reduced on rank 0, then broadcast).
// With one rank every function here returns at once and changes nothing.
#ifndef deepdraw_parallel_ranks_h
#define deepdraw_parallel_ranks_h

#include <cstddef>
#include <type_traits>
#include <utility>
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

    // Rank `rank`'s share [first, second) of n_items numbered items:
    // contiguous, in the ranks' order, their sizes differing by at most one
    // (all of them on one rank).
    std::pair<std::size_t, std::size_t>
    share(std::size_t n_items, unsigned int rank);

    // The active cells [first, second) whose elements this rank
    // evaluates: its share of the active-cell numbering.
    std::pair<unsigned int, unsigned int>
    owned_cells(unsigned int n_active_cells);

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

    // Every rank receives rank 0's bytes.
    void
    broadcast(void *data, std::size_t bytes);

    // Each rank's entries of per_cell_items, those of its owned_cells
    // (n_cells), sent to every other rank.
    void
    gather_owned_bytes(void        *data,
                       std::size_t  bytes_per_cell,
                       unsigned int n_cells);

    template <typename T>
    void
    gather_owned_cells(std::vector<T>    &per_cell_items,
                       const unsigned int n_cells)
    {
      static_assert(std::is_trivially_copyable<T>::value,
                    "cell records are sent as bytes");
      if (n_ranks() == 1 || per_cell_items.empty())
        return;
      gather_owned_bytes(per_cell_items.data(),
                         sizeof(T) * (per_cell_items.size() / n_cells),
                         n_cells);
    }
  } // namespace parallel
} // namespace deepdraw

#endif
