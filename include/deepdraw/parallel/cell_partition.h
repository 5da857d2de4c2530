// Which rank evaluates each active cell of the sheet (D215). Every rank
// holds the whole mesh (D199); the cells are divided among the ranks by
// METIS and recorded as the cells' subdomain ids, as deal.II's
// parallel::shared::Triangulation does, but on the graph of the stacks of
// cells through the thickness: a rank's cells form compact patches of
// whole columns, whose boundary (the Newton rows sent to another rank,
// D214) is short, also after a refinement, which numbers a cell's
// children after the unrefined cells.
#ifndef deepdraw_parallel_cell_partition_h
#define deepdraw_parallel_cell_partition_h

#include <deal.II/grid/tria.h>
#include <deepdraw/parallel/ranks.h>
#include <vector>

namespace deepdraw
{
  namespace parallel
  {
    // Sets every active cell's subdomain id to the rank that evaluates it:
    // METIS, run by every rank alike on the same graph (no communication,
    // so that rank 0 alone can build a mesh for --check); with one rank,
    // or no more stacks than ranks, cell i goes to rank i mod n_ranks().
    void
    partition_cells(dealii::Triangulation<3> &mesh);

    // The rank of every active cell, by active cell index.
    std::vector<unsigned int>
    cell_owners(const dealii::Triangulation<3> &mesh);

    // Whether this rank evaluates the cell.
    inline bool
    is_owned(const dealii::CellAccessor<3> &cell)
    {
      return cell.subdomain_id() == this_rank();
    }

    // The rank of every vertex: that of the first active cell (in the
    // active-cell order) that has it, the owner of its rows (D214) and the
    // rank that evaluates its contact pairs (D216).
    std::vector<unsigned int>
    vertex_owners(const dealii::Triangulation<3> &mesh);
  } // namespace parallel
} // namespace deepdraw

#endif
