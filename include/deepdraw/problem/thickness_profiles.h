// Profiles of a column quantity (thickness strain) along the OX axis and the
// diagonal OD of the blank (doc/user_guide.md §3, doc/results.md). Columns form
// the structured grid of the initial blank: column i + j (nx + 1) stands at (i
// Length/nx, j Width/ny).
#ifndef deepdraw_problem_thickness_profiles_h
#define deepdraw_problem_thickness_profiles_h

#include <utility>
#include <vector>

namespace deepdraw
{
  namespace problem
  {
    // (s0, value) pairs, s0 = initial distance from the origin (mm).
    using Profile = std::vector<std::pair<double, double>>;

    // The columns with initial y = 0, s0 = initial x.
    Profile
    profile_along_x_axis(const std::vector<double> &column_values,
                         unsigned int               elements_along_x,
                         double                     length);

    // Along the diagonal x0 = y0 from the origin to x0 = min(Length, Width),
    // at every point where it crosses a grid line x0 = i hx or y0 = j hy,
    // s0 = sqrt(2) x0. The value there is the bilinear interpolation of the
    // column values in the initial grid; where the diagonal passes through
    // a column (hx = hy) that is the column value itself.
    Profile
    profile_along_diagonal(const std::vector<double> &column_values,
                           unsigned int               elements_along_x,
                           unsigned int               elements_along_y,
                           double                     length,
                           double                     width);
  } // namespace problem
} // namespace deepdraw

#endif
