// The cells a rank evaluates, and where it keeps their records (D217). The
// material state of a cell (the history of its quadrature points, its
// enhanced parameters) lives only on the rank that evaluates the cell, in
// the active-cell order of that rank's cells; every cell's records are
// gathered only on rank 0 for a checkpoint. A refinement's new records are
// made where their parents' are and sent to their cells' ranks (D220). With
// one rank a rank's cells are all the cells, in their order.
#ifndef deepdraw_parallel_owned_cells_h
#define deepdraw_parallel_owned_cells_h

#include <algorithm>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/parallel/ranks.h>
#include <type_traits>
#include <utility>
#include <vector>

namespace deepdraw
{
  namespace parallel
  {
    class OwnedCells
    {
    public:
      OwnedCells() = default;
      // From the cells' subdomain ids (partition_cells); nothing is
      // communicated.
      explicit OwnedCells(const dealii::Triangulation<3> &mesh);

      // Active cells of the mesh, and those of this rank.
      unsigned int
      n_cells() const;
      unsigned int
      n_owned() const;
      // The place of an active cell among this rank's cells;
      // numbers::invalid_unsigned_int for another rank's cell.
      unsigned int
      slot(unsigned int active_cell_index) const;
      // The rank that evaluates an active cell.
      unsigned int
      owner(unsigned int active_cell_index) const;

      // This rank's share of records kept per cell: items_per_cell items
      // for each cell of `whole`, by active cell index; `whole` itself
      // where this rank owns every cell (one rank), not copied.
      template <typename T>
      std::vector<T>
      keep_own(std::vector<T> whole, unsigned int items_per_cell) const;
      // Every cell's records on every rank, from each rank's share.
      template <typename T>
      std::vector<T>
      gather_on_all(const std::vector<T> &own,
                    unsigned int          items_per_cell) const;
      // Every cell's records on rank 0, empty on the other ranks; rank 0
      // receives the ranks' shares one after the other, so that it holds
      // the whole records and one rank's share at a time.
      template <typename T>
      std::vector<T>
      gather_on_root(const std::vector<T> &own,
                     unsigned int          items_per_cell) const;

      // This rank's share of records that other ranks computed (D220):
      // holder_of_cell[c] is the rank that holds cell c's records, and
      // `held` this rank's held records, items_per_cell items for each cell
      // it holds, in the cells' order. Each rank sends every held cell's
      // records to the cell's owner; `held` is emptied on the way.
      template <typename T>
      std::vector<T>
      collect_from_holders(
        std::vector<T>                 &&held,
        unsigned int                     items_per_cell,
        const std::vector<unsigned int> &holder_of_cell) const;

    private:
      std::vector<unsigned int> owner_of_cell;
      std::vector<unsigned int> slot_of_cell;
      std::vector<unsigned int> cells_of_rank;

      // Copies the records of `rank`'s cells, consecutive in `share` in the
      // cells' order, to their places in `whole`.
      template <typename T>
      void
      place_share(unsigned int rank,
                  unsigned int items_per_cell,
                  const T     *share,
                  T           *whole) const;
    };


    template <typename T>
    void
    OwnedCells::place_share(const unsigned int rank,
                            const unsigned int items_per_cell,
                            const T           *share,
                            T                 *whole) const
    {
      std::size_t position = 0;
      for (std::size_t cell = 0; cell < owner_of_cell.size(); ++cell)
        if (owner_of_cell[cell] == rank)
          for (unsigned int i = 0; i < items_per_cell; ++i)
            whole[cell * items_per_cell + i] = share[position++];
    }


    template <typename T>
    std::vector<T>
    OwnedCells::keep_own(std::vector<T>     whole,
                         const unsigned int items_per_cell) const
    {
      if (n_owned() == n_cells())
        return whole;
      std::vector<T> own;
      own.reserve(std::size_t(n_owned()) * items_per_cell);
      for (std::size_t cell = 0; cell < owner_of_cell.size(); ++cell)
        if (slot_of_cell[cell] != dealii::numbers::invalid_unsigned_int)
          own.insert(own.end(),
                     whole.begin() + cell * items_per_cell,
                     whole.begin() + (cell + 1) * items_per_cell);
      return own;
    }


    template <typename T>
    std::vector<T>
    OwnedCells::gather_on_all(const std::vector<T> &own,
                              const unsigned int    items_per_cell) const
    {
      static_assert(std::is_trivially_copyable<T>::value,
                    "records are sent as bytes");
      if (n_ranks() == 1)
        return own;
      std::vector<T> whole(std::size_t(n_cells()) * items_per_cell);
      place_share(this_rank(), items_per_cell, own.data(), whole.data());
      gather_from_owners(whole, owner_of_cell);
      return whole;
    }


    template <typename T>
    std::vector<T>
    OwnedCells::gather_on_root(const std::vector<T> &own,
                               const unsigned int    items_per_cell) const
    {
      static_assert(std::is_trivially_copyable<T>::value,
                    "records are sent as bytes");
      if (n_ranks() == 1)
        return own;
      std::vector<T> whole;
      if (is_root())
      {
        whole.resize(std::size_t(n_cells()) * items_per_cell);
        place_share(0, items_per_cell, own.data(), whole.data());
      }
      std::vector<T> share;
      for (unsigned int rank = 1; rank < n_ranks(); ++rank)
      {
        const std::size_t n_items
          = std::size_t(cells_of_rank[rank]) * items_per_cell;
        if (is_root())
          share.resize(n_items);
        send_to_root(own.data(), share.data(), n_items * sizeof(T), rank);
        if (is_root())
          place_share(rank, items_per_cell, share.data(), whole.data());
      }
      return whole;
    }


    template <typename T>
    std::vector<T>
    OwnedCells::collect_from_holders(
      std::vector<T>                 &&held,
      const unsigned int               items_per_cell,
      const std::vector<unsigned int> &holder_of_cell) const
    {
      static_assert(std::is_trivially_copyable<T>::value,
                    "records are sent as bytes");
      if (n_ranks() == 1 || items_per_cell == 0)
        return std::move(held);
      const unsigned int       me = this_rank();
      std::vector<std::size_t> n_out(n_ranks(), 0), n_in(n_ranks(), 0);
      for (std::size_t cell = 0; cell < owner_of_cell.size(); ++cell)
      {
        n_out[owner_of_cell[cell]] += holder_of_cell[cell] == me;
        n_in[holder_of_cell[cell]] += owner_of_cell[cell] == me;
      }
      // Where each rank's records start among records grouped by rank.
      const auto starts = [](const std::vector<std::size_t> &counts)
      {
        std::vector<std::size_t> first(counts.size(), 0);
        for (std::size_t rank = 1; rank < counts.size(); ++rank)
          first[rank] = first[rank - 1] + counts[rank - 1];
        return first;
      };
      // The held records by their owner, each owner's in the cells' order.
      std::vector<std::size_t> next = starts(n_out);
      std::vector<T>           out(held.size());
      std::size_t              position = 0;
      for (std::size_t cell = 0; cell < owner_of_cell.size(); ++cell)
        if (holder_of_cell[cell] == me)
          std::copy_n(held.begin() + items_per_cell * position++,
                      items_per_cell,
                      out.begin()
                        + items_per_cell * next[owner_of_cell[cell]]++);
      std::vector<T>().swap(held);
      std::vector<T> in(std::size_t(n_owned()) * items_per_cell);
      exchange_records(out.data(),
                       n_out,
                       in.data(),
                       n_in,
                       items_per_cell * sizeof(T));
      std::vector<T>().swap(out);
      // Received by holder, each holder's in the cells' order.
      next = starts(n_in);
      std::vector<T> own(in.size());
      for (std::size_t cell = 0; cell < owner_of_cell.size(); ++cell)
        if (owner_of_cell[cell] == me)
          std::copy_n(in.begin()
                        + items_per_cell * next[holder_of_cell[cell]]++,
                      items_per_cell,
                      own.begin() + items_per_cell * slot_of_cell[cell]);
      return own;
    }
  } // namespace parallel
} // namespace deepdraw

#endif
