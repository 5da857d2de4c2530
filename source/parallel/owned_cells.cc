#include <deepdraw/parallel/cell_partition.h>
#include <deepdraw/parallel/owned_cells.h>
#include <stdexcept>
#include <string>

namespace deepdraw
{
  namespace parallel
  {
    OwnedCells::OwnedCells(const dealii::Triangulation<3> &mesh)
        : owner_of_cell(cell_owners(mesh))
        , slot_of_cell(owner_of_cell.size(),
                       dealii::numbers::invalid_unsigned_int)
        , cells_of_rank(n_ranks(), 0)
    {
      const unsigned int me = this_rank();
      for (std::size_t cell = 0; cell < owner_of_cell.size(); ++cell)
      {
        const unsigned int owner = owner_of_cell[cell];
        if (owner >= cells_of_rank.size())
          throw std::logic_error("a cell of subdomain " + std::to_string(owner)
                                 + " with " + std::to_string(n_ranks())
                                 + " ranks: the mesh is not partitioned");
        if (owner == me)
          slot_of_cell[cell] = cells_of_rank[me];
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


    unsigned int
    OwnedCells::owner(const unsigned int active_cell_index) const
    {
      return owner_of_cell[active_cell_index];
    }
  } // namespace parallel
} // namespace deepdraw
