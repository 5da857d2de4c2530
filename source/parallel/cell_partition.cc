#include <algorithm>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deepdraw/parallel/cell_partition.h>

namespace deepdraw
{
  namespace parallel
  {
    namespace
    {
      // The stack of each active cell: the cells joined through their
      // faces 4 and 5, the sheet's thickness direction (the blank's mesh is
      // extruded, and refinement keeps the faces' numbers, D82). A union
      // find; the stacks numbered 0, 1, ... in the order of their first
      // cell.
      std::vector<unsigned int>
      stacks_of_cells(const dealii::Triangulation<3> &mesh,
                      unsigned int                   &n_stacks)
      {
        std::vector<unsigned int> parent(mesh.n_active_cells());
        for (unsigned int i = 0; i < parent.size(); ++i)
          parent[i] = i;
        const auto root = [&parent](unsigned int i)
        {
          while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
          return i;
        };
        // A refined neighbour's children join from their side.
        for (const auto &cell : mesh.active_cell_iterators())
          for (const unsigned int f : {4u, 5u})
            if (!cell->at_boundary(f) && !cell->neighbor(f)->has_children())
            {
              const unsigned int a = root(cell->active_cell_index()),
                                 b
                                 = root(cell->neighbor(f)->active_cell_index());
              parent[std::max(a, b)] = std::min(a, b);
            }
        std::vector<unsigned int> stack(parent.size());
        std::vector<unsigned int> number(parent.size(),
                                         dealii::numbers::invalid_unsigned_int);
        n_stacks = 0;
        for (unsigned int i = 0; i < parent.size(); ++i)
        {
          const unsigned int r = root(i);
          if (number[r] == dealii::numbers::invalid_unsigned_int)
            number[r] = n_stacks++;
          stack[i] = number[r];
        }
        return stack;
      }
    } // namespace


    void
    partition_cells(dealii::Triangulation<3> &mesh)
    {
      const unsigned int              n        = n_ranks();
      unsigned int                    n_stacks = 0;
      const std::vector<unsigned int> stack
        = n > 1 ? stacks_of_cells(mesh, n_stacks) : std::vector<unsigned int>();
      if (n_stacks <= n)
      {
        for (const auto &cell : mesh.active_cell_iterators())
          cell->set_subdomain_id(cell->active_cell_index() % n);
        return;
      }
      // METIS on the graph of the stacks (neighbours through the faces
      // 0-3), weighted by their cells: a sheet is cut across its plane
      // only, and the ranks get equal numbers of cells (D215). METIS's
      // default options fix its random seed, so every rank computes the
      // same partition; the ranks compare theirs at the first assembly
      // (linear_algebra::RowPartition).
      dealii::DynamicSparsityPattern graph(n_stacks);
      std::vector<unsigned int>      cells_of_stack(n_stacks, 0);
      for (const auto &cell : mesh.active_cell_iterators())
      {
        const unsigned int s = stack[cell->active_cell_index()];
        ++cells_of_stack[s];
        graph.add(s, s);
        for (const unsigned int f : {0u, 1u, 2u, 3u})
          if (!cell->at_boundary(f) && !cell->neighbor(f)->has_children())
          {
            const unsigned int t
              = stack[cell->neighbor(f)->active_cell_index()];
            graph.add(s, t);
            graph.add(t, s);
          }
      }
      dealii::SparsityPattern pattern;
      pattern.copy_from(graph);
      std::vector<unsigned int> rank_of_stack(n_stacks);
      dealii::SparsityTools::partition(
        pattern,
        cells_of_stack,
        n,
        rank_of_stack,
        dealii::SparsityTools::Partitioner::metis);
      for (const auto &cell : mesh.active_cell_iterators())
        cell->set_subdomain_id(rank_of_stack[stack[cell->active_cell_index()]]);
    }


    std::vector<unsigned int>
    cell_owners(const dealii::Triangulation<3> &mesh)
    {
      std::vector<unsigned int> owners(mesh.n_active_cells());
      for (const auto &cell : mesh.active_cell_iterators())
        owners[cell->active_cell_index()] = cell->subdomain_id();
      return owners;
    }


    std::vector<unsigned int>
    vertex_owners(const dealii::Triangulation<3> &mesh)
    {
      std::vector<unsigned int> owners(mesh.n_vertices(),
                                       dealii::numbers::invalid_unsigned_int);
      for (const auto &cell : mesh.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          if (owners[cell->vertex_index(v)]
              == dealii::numbers::invalid_unsigned_int)
            owners[cell->vertex_index(v)] = cell->subdomain_id();
      return owners;
    }
  } // namespace parallel
} // namespace deepdraw
