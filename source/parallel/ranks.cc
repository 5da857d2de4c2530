#include <algorithm>
#include <deepdraw/parallel/ranks.h>
#include <mpi.h>
#include <vector>

namespace deepdraw
{
  namespace parallel
  {
    namespace
    {
      // MPI counts are int: long arrays go in pieces.
      constexpr std::size_t largest_piece = std::size_t(1) << 28;

      bool
      mpi_running()
      {
        int initialized = 0, finalized = 0;
        MPI_Initialized(&initialized);
        MPI_Finalized(&finalized);
        return initialized != 0 && finalized == 0;
      }
    } // namespace


    unsigned int
    n_ranks()
    {
      if (!mpi_running())
        return 1;
      int size = 1;
      MPI_Comm_size(MPI_COMM_WORLD, &size);
      return size;
    }


    unsigned int
    this_rank()
    {
      if (!mpi_running())
        return 0;
      int rank = 0;
      MPI_Comm_rank(MPI_COMM_WORLD, &rank);
      return rank;
    }


    bool
    is_root()
    {
      return this_rank() == 0;
    }


    std::pair<unsigned int, unsigned int>
    owned_cells(const unsigned int n_active_cells)
    {
      const unsigned long long n = n_ranks(), rank = this_rank();
      return {static_cast<unsigned int>(n_active_cells * rank / n),
              static_cast<unsigned int>(n_active_cells * (rank + 1) / n)};
    }


    void
    sum(double *values, const std::size_t n)
    {
      if (n_ranks() == 1)
        return;
      // Reduced on rank 0 and broadcast, rather than MPI_Allreduce: the
      // standard does not promise every rank the same rounding, and the
      // ranks' decisions (contact states, convergence) must agree.
      std::vector<double> piece;
      for (std::size_t first = 0; first < n; first += largest_piece)
      {
        const int count = std::min(largest_piece, n - first);
        if (is_root())
          MPI_Reduce(MPI_IN_PLACE,
                     values + first,
                     count,
                     MPI_DOUBLE,
                     MPI_SUM,
                     0,
                     MPI_COMM_WORLD);
        else
          MPI_Reduce(values + first,
                     nullptr,
                     count,
                     MPI_DOUBLE,
                     MPI_SUM,
                     0,
                     MPI_COMM_WORLD);
      }
      broadcast(values, n * sizeof(double));
    }


    unsigned long long
    sum(const unsigned long long value)
    {
      unsigned long long result = value;
      if (n_ranks() > 1)
        MPI_Allreduce(&value,
                      &result,
                      1,
                      MPI_UNSIGNED_LONG_LONG,
                      MPI_SUM,
                      MPI_COMM_WORLD);
      return result;
    }


    int
    maximum(const int value)
    {
      int result = value;
      if (n_ranks() > 1)
        MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
      return result;
    }


    namespace
    {
      void
      broadcast_from(void *data, const std::size_t bytes, const int root)
      {
        char *bytes_data = static_cast<char *>(data);
        for (std::size_t first = 0; first < bytes; first += largest_piece)
          MPI_Bcast(bytes_data + first,
                    std::min(largest_piece, bytes - first),
                    MPI_BYTE,
                    root,
                    MPI_COMM_WORLD);
      }
    } // namespace


    void
    barrier()
    {
      if (n_ranks() > 1)
        MPI_Barrier(MPI_COMM_WORLD);
    }


    void
    broadcast(void *data, const std::size_t bytes)
    {
      if (n_ranks() > 1)
        broadcast_from(data, bytes, 0);
    }


    void
    gather_owned_bytes(void              *data,
                       const std::size_t  bytes_per_cell,
                       const unsigned int n_cells)
    {
      const unsigned long long n = n_ranks();
      for (unsigned long long rank = 0; rank < n; ++rank)
      {
        const std::size_t first = n_cells * rank / n;
        const std::size_t end   = n_cells * (rank + 1) / n;
        broadcast_from(static_cast<char *>(data) + first * bytes_per_cell,
                       (end - first) * bytes_per_cell,
                       rank);
      }
    }
  } // namespace parallel
} // namespace deepdraw
