#include <algorithm>
#include <cstdint>
#include <cstring>
#include <deal.II/base/mpi.h>
#include <deepdraw/parallel/ranks.h>
#include <limits>
#include <mpi.h>
#include <stdexcept>

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


    unsigned int
    ranks_on_this_machine()
    {
      static const unsigned int count = []
      {
        if (n_ranks() == 1)
          return 1u;
        MPI_Comm machine = MPI_COMM_NULL;
        MPI_Comm_split_type(MPI_COMM_WORLD,
                            MPI_COMM_TYPE_SHARED,
                            0,
                            MPI_INFO_NULL,
                            &machine);
        int size = 1;
        MPI_Comm_size(machine, &size);
        MPI_Comm_free(&machine);
        return static_cast<unsigned int>(size);
      }();
      return count;
    }


    void
    sum(double *values, const std::size_t n)
    {
      if (n_ranks() == 1)
        return;
      // Reduced on rank 0 and broadcast, rather than MPI_Allreduce: the
      // standard does not promise every rank the same rounding, and the
      // ranks' decisions (contact states, convergence) must agree.
      for (std::size_t first = 0; first < n; first += largest_piece)
        MPI_Reduce(is_root() ? MPI_IN_PLACE : values + first,
                   values + first,
                   std::min(largest_piece, n - first),
                   MPI_DOUBLE,
                   MPI_SUM,
                   0,
                   MPI_COMM_WORLD);
      broadcast(values, n * sizeof(double));
    }


    // Integers: every rank gets the exact result from deal.II's
    // MPI_Allreduce.
    unsigned long long
    sum(const unsigned long long value)
    {
      return n_ranks() == 1
               ? value
               : dealii::Utilities::MPI::sum(value, MPI_COMM_WORLD);
    }


    int
    maximum(const int value)
    {
      return n_ranks() == 1
               ? value
               : dealii::Utilities::MPI::max(value, MPI_COMM_WORLD);
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


    namespace
    {
      // Vectors of trivially copyable items to each rank: the receivers
      // learn their counts first, then exchange_records moves the items.
      template <typename T>
      void
      exchange_items(const std::vector<std::vector<T>> &to_rank,
                     std::vector<std::vector<T>>       &from_rank)
      {
        static_assert(sizeof(std::size_t) == sizeof(std::uint64_t),
                      "counts are sent as 64-bit integers");
        const unsigned int n = n_ranks();
        from_rank.assign(n, {});
        if (n == 1)
        {
          from_rank[0] = to_rank[0];
          return;
        }
        std::vector<std::size_t> send_counts(n), receive_counts(n);
        std::vector<T>           sent;
        for (unsigned int r = 0; r < n; ++r)
        {
          send_counts[r] = to_rank[r].size();
          sent.insert(sent.end(), to_rank[r].begin(), to_rank[r].end());
        }
        MPI_Alltoall(send_counts.data(),
                     1,
                     MPI_UINT64_T,
                     receive_counts.data(),
                     1,
                     MPI_UINT64_T,
                     MPI_COMM_WORLD);
        std::size_t total = 0;
        for (const std::size_t count : receive_counts)
          total += count;
        std::vector<T> received(total);
        exchange_records(sent.data(),
                         send_counts,
                         received.data(),
                         receive_counts,
                         sizeof(T));
        auto first = received.begin();
        for (unsigned int r = 0; r < n; ++r)
        {
          from_rank[r].assign(first, first + receive_counts[r]);
          first += receive_counts[r];
        }
      }
    } // namespace


    void
    exchange(const std::vector<std::vector<double>> &to_rank,
             std::vector<std::vector<double>>       &from_rank)
    {
      exchange_items(to_rank, from_rank);
    }


    void
    exchange(const std::vector<std::vector<unsigned long long>> &to_rank,
             std::vector<std::vector<unsigned long long>>       &from_rank)
    {
      exchange_items(to_rank, from_rank);
    }


    void
    barrier()
    {
      if (n_ranks() > 1)
        MPI_Barrier(MPI_COMM_WORLD);
    }


    void
    broadcast(void *data, const std::size_t bytes, const unsigned int root)
    {
      if (n_ranks() > 1)
        broadcast_from(data, bytes, root);
    }


    void
    send_to_root(const void        *sent,
                 void              *received,
                 const std::size_t  bytes,
                 const unsigned int from)
    {
      const unsigned int me = this_rank();
      if (from == 0 || (me != from && me != 0))
        return;
      for (std::size_t first = 0; first < bytes; first += largest_piece)
      {
        const int count = std::min(largest_piece, bytes - first);
        if (me == from)
          MPI_Send(static_cast<const char *>(sent) + first,
                   count,
                   MPI_BYTE,
                   0,
                   0,
                   MPI_COMM_WORLD);
        else
          MPI_Recv(static_cast<char *>(received) + first,
                   count,
                   MPI_BYTE,
                   from,
                   0,
                   MPI_COMM_WORLD,
                   MPI_STATUS_IGNORE);
      }
    }


    void
    exchange_records(const void                     *sent,
                     const std::vector<std::size_t> &sent_counts,
                     void                           *received,
                     const std::vector<std::size_t> &receive_counts,
                     const std::size_t               bytes_per_record)
    {
      const unsigned int n = n_ranks();
      if (n == 1)
      {
        std::memcpy(received, sent, sent_counts[0] * bytes_per_record);
        return;
      }
      // Counted in records, not bytes, so that MPI's int counts reach far.
      const auto as_int = [](const std::size_t value)
      {
        if (value > std::size_t(std::numeric_limits<int>::max()))
          throw std::overflow_error("exchange_records: more records than "
                                    "an MPI count holds");
        return int(value);
      };
      std::vector<int> counts_out(n), offsets_out(n), counts_in(n),
        offsets_in(n);
      std::size_t sent_so_far = 0, received_so_far = 0;
      for (unsigned int r = 0; r < n; ++r)
      {
        counts_out[r]  = as_int(sent_counts[r]);
        offsets_out[r] = as_int(sent_so_far);
        counts_in[r]   = as_int(receive_counts[r]);
        offsets_in[r]  = as_int(received_so_far);
        sent_so_far += sent_counts[r];
        received_so_far += receive_counts[r];
      }
      MPI_Datatype record;
      MPI_Type_contiguous(as_int(bytes_per_record), MPI_BYTE, &record);
      MPI_Type_commit(&record);
      MPI_Alltoallv(sent,
                    counts_out.data(),
                    offsets_out.data(),
                    record,
                    received,
                    counts_in.data(),
                    offsets_in.data(),
                    record,
                    MPI_COMM_WORLD);
      MPI_Type_free(&record);
    }


    void
    gather_from_owners(void                            *data,
                       const std::size_t                bytes_per_owner,
                       const std::vector<unsigned int> &owners)
    {
      char *const        bytes = static_cast<char *>(data);
      std::vector<char>  packed;
      const unsigned int me = this_rank();
      for (unsigned int rank = 0; rank < n_ranks(); ++rank)
      {
        std::size_t n_records = 0;
        for (const unsigned int owner : owners)
          n_records += owner == rank;
        packed.resize(n_records * bytes_per_owner);
        // The owner packs its records in their order, and every other rank
        // unpacks them in the same order.
        std::size_t position = 0;
        for (std::size_t i = 0; i < owners.size(); ++i)
          if (owners[i] == rank)
          {
            if (rank == me)
              std::memcpy(packed.data() + position,
                          bytes + i * bytes_per_owner,
                          bytes_per_owner);
            position += bytes_per_owner;
          }
        broadcast(packed.data(), packed.size(), rank);
        if (rank == me)
          continue;
        position = 0;
        for (std::size_t i = 0; i < owners.size(); ++i)
          if (owners[i] == rank)
          {
            std::memcpy(bytes + i * bytes_per_owner,
                        packed.data() + position,
                        bytes_per_owner);
            position += bytes_per_owner;
          }
      }
    }
  } // namespace parallel
} // namespace deepdraw
