// Sampling of the thickness-strain profiles OX and OD in the structured
// column grid (problem/thickness_profiles.h): with a bilinear column field
// f(x, y) = 1 + 2x - 3y + 0.5xy, bilinear interpolation is exact, so every
// sample must equal f at its point; on a square grid the diagonal samples
// are the column values themselves.
#include "test_utilities.h"

#include <cmath>
#include <deepdraw/problem/thickness_profiles.h>
#include <string>
#include <vector>

using namespace deepdraw::problem;
using namespace deepdraw_test;

namespace
{
  double
  field(const double x, const double y)
  {
    return 1. + 2. * x - 3. * y + 0.5 * x * y;
  }

  std::vector<double>
  column_values(const unsigned int nx,
                const unsigned int ny,
                const double       length,
                const double       width)
  {
    std::vector<double> values((nx + 1) * (ny + 1));
    for (unsigned int j = 0; j <= ny; ++j)
      for (unsigned int i = 0; i <= nx; ++i)
        values[i + j * (nx + 1)] = field(i * length / nx, j * width / ny);
    return values;
  }

  void
  check_grid(const unsigned int         nx,
             const unsigned int         ny,
             const double               length,
             const double               width,
             const std::vector<double> &expected_x0,
             const std::string         &name)
  {
    std::cout << name << std::endl;
    const std::vector<double> values = column_values(nx, ny, length, width);

    const Profile ox = profile_along_x_axis(values, nx, length);
    check_true("OX has nx + 1 rows", ox.size() == nx + 1);
    for (unsigned int i = 0; i < ox.size(); ++i)
    {
      check_close("OX s0", ox[i].first, i * length / nx, 1e-14);
      check_close("OX value", ox[i].second, field(ox[i].first, 0.), 1e-13);
    }

    const Profile od = profile_along_diagonal(values, nx, ny, length, width);
    check_true("OD rows " + std::to_string(od.size()) + " expected "
                 + std::to_string(expected_x0.size()),
               od.size() == expected_x0.size());
    for (unsigned int k = 0; k < std::min(od.size(), expected_x0.size()); ++k)
    {
      const double x0 = expected_x0[k];
      check_close("OD s0", od[k].first, std::sqrt(2.) * x0, 1e-13);
      check_close("OD value", od[k].second, field(x0, x0), 1e-13);
    }
  }
} // namespace

int
main()
{
  // Square grid, equal spacing: the diagonal runs through the columns
  // (i, i), whose values are taken exactly.
  check_grid(4, 4, 2., 2., {0., 0.5, 1., 1.5, 2.}, "4 x 4 on 2 x 2");
  {
    const std::vector<double> values = column_values(4, 4, 2., 2.);
    const Profile             od = profile_along_diagonal(values, 4, 4, 2., 2.);
    for (unsigned int i = 0; i < od.size(); ++i)
      check_true("diagonal column " + std::to_string(i) + " taken exactly",
                 od[i].second == values[i + i * 5]);
  }
  // Unequal spacing: crossings of x = i/2 and y = 2j/3, merged at 0 and 2.
  check_grid(4,
             3,
             2.,
             2.,
             {0., 0.5, 2. / 3., 1., 4. / 3., 1.5, 2.},
             "4 x 3 on 2 x 2");
  // Narrower than long: OD ends at y0 = Width = 1.
  check_grid(4, 2, 2., 1., {0., 0.5, 1.}, "4 x 2 on 2 x 1");
  // Longer in y: OD ends at x0 = Length = 1; the lines y = 0.75 cross it.
  check_grid(2, 4, 1., 3., {0., 0.5, 0.75, 1.}, "2 x 4 on 1 x 3");
  return summary();
}
