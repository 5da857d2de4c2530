// Each vertex's share of the sheet's top and bottom faces (boundary ids 4
// and 5): a quarter of every adjacent active face. Turns nodal contact
// forces into pressures (output) and back (transfer to a refined mesh).
#ifndef deepdraw_blank_nodal_surface_area_h
#define deepdraw_blank_nodal_surface_area_h

#include <deal.II/grid/tria.h>
#include <vector>

namespace deepdraw
{
  namespace blank
  {
    using namespace dealii;

    // By vertex index, mm² (0 off the top and bottom faces).
    std::vector<double>
    nodal_surface_area(const Triangulation<3> &mesh);
  } // namespace blank
} // namespace deepdraw

#endif
