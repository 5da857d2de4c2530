// The cells divided among 3 ranks (D215) on a 12 x 12 x 2 sheet refined
// as adaptive runs refine it: a 3 x 3 patch of columns isotropically (hanging
// nodes in the plane) and another cut through the thickness only (cut_z).
// - Every stack of cells through the thickness is on one rank: a
//   neighbour through face 4 or 5 (the thickness direction) has the same
//   owner, refined neighbours included.
// - The ranks hold equal numbers of cells to within the largest stack plus
//   METIS's allowed imbalance (3 % of the mean for its k-way, 0.1 % per
//   bisection for its recursive bisection; 5 % allowed).
// - The rank boundary is short: fewer vertices on it than half of those on
//   the boundary of contiguous shares of the active-cell numbering, which
//   cut between the layers (the whole middle plane).
// - Every rank computed the same owners.
#include "test_utilities.h"

#include <algorithm>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/parallel/cell_partition.h>
#include <deepdraw/parallel/ranks.h>
#include <iostream>
#include <set>
#include <vector>

using namespace dealii;
using namespace deepdraw_test;

namespace
{
  // Vertices that cells of more than one rank share.
  unsigned int
  boundary_vertices(const Triangulation<3>          &mesh,
                    const std::vector<unsigned int> &owners)
  {
    std::vector<std::set<unsigned int>> ranks_of_vertex(mesh.n_vertices());
    for (const auto &cell : mesh.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        ranks_of_vertex[cell->vertex_index(v)].insert(
          owners[cell->active_cell_index()]);
    return std::count_if(ranks_of_vertex.begin(),
                         ranks_of_vertex.end(),
                         [](const std::set<unsigned int> &ranks)
                         { return ranks.size() > 1; });
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               n_ranks = deepdraw::parallel::n_ranks();
  Triangulation<3> mesh(Triangulation<3>::limit_level_difference_at_vertices);
  GridGenerator::subdivided_hyper_rectangle(mesh,
                                            {12, 12, 2},
                                            Point<3>(0, 0, 0),
                                            Point<3>(12, 12, 1));
  for (const auto &cell : mesh.active_cell_iterators())
  {
    const Point<3> c = cell->center();
    if (c[0] < 3 && c[1] < 3)
      cell->set_refine_flag();
    else if (c[0] > 6 && c[0] < 9 && c[1] > 6 && c[1] < 9)
      cell->set_refine_flag(RefinementCase<3>::cut_z);
  }
  mesh.execute_coarsening_and_refinement();
  deepdraw::parallel::partition_cells(mesh);
  const std::vector<unsigned int> owners
    = deepdraw::parallel::cell_owners(mesh);

  bool stacks_whole = true;
  for (const auto &cell : mesh.active_cell_iterators())
    for (const unsigned int f : {4u, 5u})
      if (!cell->at_boundary(f))
      {
        const auto neighbour = cell->neighbor(f);
        if (neighbour->has_children())
          for (unsigned int s = 0; s < cell->face(f)->n_children(); ++s)
            stacks_whole
              = stacks_whole
                && cell->neighbor_child_on_subface(f, s)->subdomain_id()
                     == cell->subdomain_id();
        else
          stacks_whole
            = stacks_whole && neighbour->subdomain_id() == cell->subdomain_id();
      }

  std::vector<unsigned int> cells_of_rank(n_ranks, 0);
  for (const unsigned int owner : owners)
    ++cells_of_rank[owner];
  const double mean = double(mesh.n_active_cells()) / n_ranks;

  std::vector<unsigned int> contiguous(owners.size());
  for (unsigned int i = 0; i < owners.size(); ++i)
    contiguous[i] = (std::size_t(i) * n_ranks) / owners.size();

  // Rank 0's owners against every rank's.
  std::vector<unsigned int> root_owners(owners);
  deepdraw::parallel::broadcast(root_owners.data(),
                                root_owners.size() * sizeof(unsigned int));
  const int differs
    = deepdraw::parallel::maximum(root_owners != owners ? 1 : 0);

  if (deepdraw::parallel::is_root())
  {
    std::cout << mesh.n_active_cells() << " cells on " << n_ranks << " ranks:";
    for (const unsigned int n : cells_of_rank)
      std::cout << ' ' << n;
    std::cout << "; boundary vertices " << boundary_vertices(mesh, owners)
              << " (contiguous shares " << boundary_vertices(mesh, contiguous)
              << ")\n";
    check_true("run on 3 ranks", n_ranks == 3);
    check_true("every stack through the thickness on one rank", stacks_whole);
    // The largest stack: 4 cells (the cut_z columns, and the isotropic
    // ones: two children high in each of the two layers).
    for (unsigned int r = 0; r < n_ranks; ++r)
      check_close("cells of rank " + std::to_string(r),
                  cells_of_rank[r],
                  mean,
                  4 + 0.05 * mean);
    check_true("boundary under half the contiguous shares'",
               2 * boundary_vertices(mesh, owners)
                 < boundary_vertices(mesh, contiguous));
    check_true("every rank computed the same owners", differs == 0);
  }
  return deepdraw::parallel::is_root() ? summary() : 0;
}
