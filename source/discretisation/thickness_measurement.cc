#include <deepdraw/discretisation/thickness_measurement.h>
#include <deepdraw/io/input_error.h>
#include <string>

namespace deepdraw
{
  namespace discretisation
  {
    void
    ThicknessMeasurement::set_up(const Triangulation<3>      &mesh,
                                 const std::vector<Point<3>> &initial_vertices)
    {
      sheet = std::make_unique<blank::SheetThickness>(mesh, initial_vertices);
      vertex_locations.assign(initial_vertices.size(),
                              blank::SheetThickness::Location());
      for (const auto &cell : mesh.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
        {
          const Point<3> &X        = initial_vertices[cell->vertex_index(v)];
          const auto      location = sheet->locate(Point<2>(X[0], X[1]));
          if (!location)
            throw InputError("Geometry: the vertex at (" + std::to_string(X[0])
                             + ", " + std::to_string(X[1])
                             + ") is not over both the bottom and the top "
                               "face of the sheet mesh");
          vertex_locations[cell->vertex_index(v)] = *location;
        }
    }


    void
    ThicknessMeasurement::update(const Triangulation<3> &mesh,
                                 const double            nominal_thickness)
    {
      // (x_top - x_bottom) . n with n the mean sheet normal there.
      const auto &vertices = mesh.get_vertices();
      sheet->update(vertices);
      thickness.assign(vertices.size(), nominal_thickness);
      for (const auto &cell : mesh.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
        {
          const unsigned int vertex = cell->vertex_index(v);
          thickness[vertex]
            = sheet->thickness(vertex_locations[vertex], vertices);
        }
    }


    const blank::SheetThickness &
    ThicknessMeasurement::sheet_thickness() const
    {
      return *sheet;
    }


    const std::vector<double> &
    ThicknessMeasurement::vertex_thickness() const
    {
      return thickness;
    }
  } // namespace discretisation
} // namespace deepdraw
