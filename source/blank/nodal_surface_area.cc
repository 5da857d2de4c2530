#include <deepdraw/blank/nodal_surface_area.h>

namespace deepdraw
{
  namespace blank
  {
    std::vector<double>
    nodal_surface_area(const Triangulation<3> &mesh)
    {
      std::vector<double> area(mesh.n_vertices(), 0.);
      for (const auto &cell : mesh.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary()
              && (face->boundary_id() == 4 || face->boundary_id() == 5))
            for (const unsigned int v : face->vertex_indices())
              area[face->vertex_index(v)] += face->measure() / 4.;
      return area;
    }
  } // namespace blank
} // namespace deepdraw
