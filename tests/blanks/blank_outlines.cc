// The meshes of Blank outline = circle and polygon (doc/user_guide.md §2.1,
// D70, D71) against independent expectations:
//  - circle of diameter D: the rim vertices lie on the circle at equal
//    angles (2m per quadrant, m = BlankGeometry::disc_square_cells(n)), so
//    the mesh is the inscribed polygon: volume = q m R^2 sin(pi/(4m)) t for
//    q quadrants, to round-off (1e-12 relative), and below the disc's
//    q/4 pi R^2 t by the polygon's deficit 1 - sin(phi)/phi < phi^2/6;
//  - a square outline (corners at 45 deg, where the mesh has rim vertices)
//    and a diamond (corners on the axes): every rim edge lies on a side, so
//    the volume is the polygon's exactly (1e-12);
//  - radius() of the polygon along a few directions, closed form;
//  - the boundary ids: bottom and top areas, symmetry planes on x = 0 and
//    y = 0 only where modelled, the rim elsewhere.
#include "test_utilities.h"

#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/blank/blank_geometry.h>
#include <deepdraw/blank/blank_outline.h>
#include <filesystem>
#include <fstream>
#include <string>

using namespace dealii;
using namespace deepdraw::blank;
using namespace deepdraw_test;

namespace
{
  BlankGeometry
  parse(const std::string &outline,
        const std::string &planes,
        const std::string &file = "")
  {
    ParameterHandler prm;
    BlankGeometry::declare_parameters(prm);
    prm.enter_subsection("Geometry");
    prm.set("Blank outline", outline);
    prm.set("Diameter", "80");
    prm.set("Thickness", "0.5");
    prm.set("Elements along radius", "9");
    prm.set("Symmetry planes", planes);
    prm.set("Outline file", file);
    prm.leave_subsection();
    BlankGeometry geometry;
    geometry.parse_parameters(prm);
    return geometry;
  }

  // Area of the faces of one boundary id.
  double
  face_area(const Triangulation<3> &triangulation, const unsigned int id)
  {
    double area = 0.;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == id)
          area += face->measure();
    return area;
  }

  void
  check_circle(const std::string &planes, const unsigned int quadrants)
  {
    const BlankGeometry geometry = parse("circle", planes);
    Triangulation<3>    triangulation;
    geometry.create_mesh(triangulation);
    const unsigned int m = BlankGeometry::disc_square_cells(9);
    const double       R = 40., t = 0.5, phi = M_PI / (4. * m);
    const double       polygon = quadrants * m * R * R * std::sin(phi) * t;
    const double       disc    = quadrants / 4. * M_PI * R * R * t;
    const double       volume  = GridTools::volume(triangulation);
    std::cout << "circle, planes '" << planes << "'" << std::endl;
    check_relative("volume = inscribed polygon x t", volume, polygon, 1e-12);
    check_true("below the disc by less than phi^2/6",
               volume < disc && (disc - volume) / disc < phi * phi / 6.);
    check_close("cells counted before meshing",
                triangulation.n_active_cells(),
                geometry.n_cells(),
                0.);
    check_relative("bottom area",
                   face_area(triangulation, 4),
                   polygon / t,
                   1e-12);
    check_relative("top area", face_area(triangulation, 5), polygon / t, 1e-12);
    // A plane of the quarter model spans R, of the half model 2R.
    const double plane_area = (quadrants == 1 ? 1. : 2.) * R * t;
    check_relative("symmetry plane x = 0",
                   face_area(triangulation, 0),
                   planes.find('x') != std::string::npos ? plane_area : 0.,
                   1e-12,
                   1.);
    check_relative("symmetry plane y = 0",
                   face_area(triangulation, 2),
                   planes.find('y') != std::string::npos ? plane_area : 0.,
                   1e-12,
                   1.);
    check_relative("rim: 2m q edges of length 2 R sin(phi/2)",
                   face_area(triangulation, 1),
                   2. * m * quadrants * 2. * R * std::sin(phi / 2.) * t,
                   1e-12);
  }

  void
  check_polygon(const std::string &name,
                const std::string &corners,
                const double       quarter_area)
  {
    const std::string file
      = (std::filesystem::temp_directory_path() / ("outline_" + name + ".txt"))
          .string();
    std::ofstream(file) << "# " << name << "\n" << corners;
    for (const auto &[planes, quadrants] :
         {std::pair<std::string, unsigned>{"x, y", 1}, {"x", 2}, {"", 4}})
    {
      const BlankGeometry geometry = parse("polygon", planes, file);
      Triangulation<3>    triangulation;
      geometry.create_mesh(triangulation);
      std::cout << name << ", planes '" << planes << "'" << std::endl;
      check_relative("volume = polygon area x t",
                     GridTools::volume(triangulation),
                     quadrants * quarter_area * 0.5,
                     1e-12);
    }
    std::filesystem::remove(file);
  }
} // namespace


int
main()
{
  check_circle("x, y", 1);
  check_circle("y", 2);
  check_circle("x", 2);
  check_circle("", 4);
  // Square of half-width 30 (clockwise, to check the orientation), diamond
  // of half-diagonal 30 with the first corner repeated at the end.
  check_polygon("square", "30 30\n30 -30\n-30 -30\n-30 30\n", 900.);
  check_polygon("diamond", "30 0\n0 30\n-30 0\n0 -30\n30 0\n", 450.);

  const std::string file
    = (std::filesystem::temp_directory_path() / "outline_rectangle.txt")
        .string();
  std::ofstream(file) << "-20 -10\n20 -10\n20 10 # corner\n\n-20 10\n";
  const BlankOutline rectangle = BlankOutline::read(file);
  std::filesystem::remove(file);
  std::cout << "radius of the 40 x 20 rectangle" << std::endl;
  check_close("along x", rectangle.radius(0.), 20., 1e-12);
  check_close("along y", rectangle.radius(M_PI / 2.), 10., 1e-12);
  check_close("along -x", rectangle.radius(M_PI), 20., 1e-12);
  check_close("at 20 deg",
              rectangle.radius(M_PI / 9.),
              20. / std::cos(M_PI / 9.),
              1e-12);
  check_close("at 60 deg",
              rectangle.radius(M_PI / 3.),
              10. / std::sin(M_PI / 3.),
              1e-12);
  check_close("largest radius",
              rectangle.max_radius(),
              std::hypot(20., 10.),
              1e-12);
  return summary();
}
