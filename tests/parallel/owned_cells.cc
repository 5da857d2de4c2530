// The state of a cell kept by the rank that evaluates it (D217), on 3
// ranks and a 12 x 12 x 2 sheet with a 3 x 3 patch of columns refined
// isotropically (cells numbered out of their geometric order). Each cell
// has two records of 40 bytes that name the cell and the item, so that
// every place is checked against an independent expectation:
// - a rank's slots number its cells 0, 1, ... in the active-cell order,
//   and the ranks' cells add up to the mesh's, each cell on one rank;
// - keep_own leaves a rank exactly the records of its cells, in order;
// - gather_on_all gives every rank every cell's records at their places;
// - gather_on_root gives rank 0 the same and the other ranks nothing;
// - collect_from_holders gives each rank its cells' records from the ranks
//   that held them (D220: a refinement's children, made by the rank that
//   held the parent), with holders unlike the owners and rank 1 holding
//   none.
#include "test_utilities.h"

#include <array>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/parallel/cell_partition.h>
#include <deepdraw/parallel/owned_cells.h>
#include <iostream>
#include <vector>

using namespace dealii;
using namespace deepdraw_test;

namespace
{
  // A record of 40 bytes: the cell, the item within the cell, and padding
  // that marks it as written.
  struct Record
  {
    unsigned int          cell = 0, item = 0;
    std::array<double, 4> mark = {{0., 0., 0., 0.}};
  };

  constexpr unsigned int items_per_cell = 2;

  std::vector<Record>
  records_of_every_cell(const unsigned int n_cells)
  {
    std::vector<Record> whole(n_cells * items_per_cell);
    for (unsigned int c = 0; c < n_cells; ++c)
      for (unsigned int i = 0; i < items_per_cell; ++i)
        whole[c * items_per_cell + i] = {c, i, {{1., 2., 3., double(c)}}};
    return whole;
  }

  bool
  same(const std::vector<Record> &a, const std::vector<Record> &b)
  {
    if (a.size() != b.size())
      return false;
    for (std::size_t k = 0; k < a.size(); ++k)
      if (a[k].cell != b[k].cell || a[k].item != b[k].item
          || a[k].mark != b[k].mark)
        return false;
    return true;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  namespace parallel = deepdraw::parallel;
  Triangulation<3> mesh(Triangulation<3>::limit_level_difference_at_vertices);
  GridGenerator::subdivided_hyper_rectangle(mesh,
                                            {12, 12, 2},
                                            Point<3>(0, 0, 0),
                                            Point<3>(12, 12, 1));
  for (const auto &cell : mesh.active_cell_iterators())
    if (cell->center()[0] < 3 && cell->center()[1] < 3)
      cell->set_refine_flag();
  mesh.execute_coarsening_and_refinement();
  parallel::partition_cells(mesh);
  const parallel::OwnedCells cells(mesh);
  const unsigned int         n_cells = mesh.n_active_cells();

  // The slots, and this rank's records in their order.
  bool                      slots_in_order = true;
  unsigned int              next_slot      = 0;
  std::vector<Record>       expected_own;
  const std::vector<Record> whole = records_of_every_cell(n_cells);
  for (const auto &cell : mesh.active_cell_iterators())
  {
    const unsigned int c = cell->active_cell_index();
    if (parallel::is_owned(*cell))
    {
      slots_in_order = slots_in_order && cells.slot(c) == next_slot++;
      for (unsigned int i = 0; i < items_per_cell; ++i)
        expected_own.push_back(whole[c * items_per_cell + i]);
    }
    else
      slots_in_order
        = slots_in_order && cells.slot(c) == numbers::invalid_unsigned_int;
  }
  const std::vector<Record> own = cells.keep_own(whole, items_per_cell);
  const unsigned long long  cells_of_ranks
    = parallel::sum(static_cast<unsigned long long>(cells.n_owned()));
  const int keep_wrong = parallel::maximum(same(own, expected_own) ? 0 : 1);
  const int slots_wrong
    = parallel::maximum(slots_in_order && next_slot == cells.n_owned() ? 0 : 1);
  const int all_wrong = parallel::maximum(
    same(cells.gather_on_all(own, items_per_cell), whole) ? 0 : 1);
  const std::vector<Record> at_root = cells.gather_on_root(own, items_per_cell);
  const int                 root_wrong
    = parallel::maximum(parallel::is_root() ? (same(at_root, whole) ? 0 : 1)
                                            : (at_root.empty() ? 0 : 1));
  // Cells held in blocks of 5 by ranks 0 and 2, whatever their owners.
  std::vector<unsigned int> holder(n_cells);
  std::vector<Record>       held;
  for (unsigned int c = 0; c < n_cells; ++c)
  {
    holder[c] = (c / 5) % 2 == 0 ? 0 : 2;
    if (holder[c] == parallel::this_rank())
      held.insert(held.end(),
                  whole.begin() + c * items_per_cell,
                  whole.begin() + (c + 1) * items_per_cell);
  }
  const std::vector<Record> collected
    = cells.collect_from_holders(std::move(held), items_per_cell, holder);
  const int collect_wrong
    = parallel::maximum(same(collected, expected_own) && held.empty() ? 0 : 1);
  // An empty record set (no enhanced parameters) stays empty.
  const int empty_wrong = parallel::maximum(
    cells.gather_on_all(std::vector<Record>(), 0).empty()
        && cells.gather_on_root(std::vector<Record>(), 0).empty()
        && cells.collect_from_holders(std::vector<Record>(), 0, holder).empty()
      ? 0
      : 1);

  if (parallel::is_root())
  {
    std::cout << n_cells << " cells; rank 0 holds " << cells.n_owned()
              << ", the ranks " << cells_of_ranks << '\n';
    check_true("run on 3 ranks", parallel::n_ranks() == 3);
    check_true("the ranks' cells add up to the mesh's",
               cells_of_ranks == n_cells && cells.n_cells() == n_cells);
    check_true("every rank's slots number its cells in order",
               slots_wrong == 0);
    check_true("keep_own leaves each rank its cells' records", keep_wrong == 0);
    check_true("gather_on_all: every record at its place on every rank",
               all_wrong == 0);
    check_true("gather_on_root: every record on rank 0, none elsewhere",
               root_wrong == 0);
    check_true("collect_from_holders: each rank its cells' records from "
               "their holders",
               collect_wrong == 0);
    check_true("no records stay none", empty_wrong == 0);
  }
  return parallel::is_root() ? summary() : 0;
}
