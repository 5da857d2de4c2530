#include <deepdraw/parallel/owned_cells.h>
#include <stdexcept>
#include <string>

namespace deepdraw
{
  namespace parallel
  {
    OwnedCells::OwnedCells(const dealii::Triangulation<3> &mesh)
        : owner_of_cell(mesh.n_active_cells())
        , slot_of_cell(mesh.n_active_cells(),
                       dealii::numbers::invalid_unsigned_int)
        , cells_of_rank(n_ranks(), 0)
    {
      const unsigned int me = this_rank();
      for (const auto &cell : mesh.active_cell_iterators())
      {
        const unsigned int index = cell->active_cell_index();
        const unsigned int owner = cell->subdomain_id();
        if (owner >= cells_of_rank.size())
          throw std::logic_error("a cell of subdomain " + std::to_string(owner)
                                 + " with " + std::to_string(n_ranks())
                                 + " ranks: the mesh is not partitioned");
        owner_of_cell[index] = owner;
        if (owner == me)
          slot_of_cell[index] = cells_of_rank[me];
        ++cells_of_rank[owner];
      }
    }


    unsigned int
    OwnedCells::n_cells() const
    {
      return owner_of_cell.size();
    }


    unsigned int
    OwnedCells::n_owned() const
    {
      return cells_of_rank.empty() ? 0 : cells_of_rank[this_rank()];
    }


    unsigned int
    OwnedCells::slot(const unsigned int active_cell_index) const
    {
      return slot_of_cell[active_cell_index];
    }
  } // namespace parallel
} // namespace deepdraw
