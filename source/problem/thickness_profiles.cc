#include <algorithm>
#include <cmath>
#include <deepdraw/problem/thickness_profiles.h>

namespace deepdraw
{
  namespace problem
  {
    namespace
    {
      // Grid interval of coordinate x (spacing h, n intervals) and the
      // local coordinate in it; snapped to the grid line within round-off
      // so that a point on a column takes the column value exactly.
      std::pair<unsigned int, double>
      locate(const double x, const double h, const unsigned int n)
      {
        const double s       = x / h;
        const bool   on_line = std::abs(s - std::round(s)) < 1e-9;
        const auto   i
          = static_cast<unsigned int>(on_line ? std::round(s) : std::floor(s));
        // The last grid line is the end of the last interval.
        if (i >= n)
          return {n - 1, 1.};
        return {i, on_line ? 0. : s - i};
      }
    } // namespace


    Profile
    profile_along_x_axis(const std::vector<double> &column_values,
                         const unsigned int         elements_along_x,
                         const double               length)
    {
      Profile profile;
      for (unsigned int i = 0; i <= elements_along_x; ++i)
        profile.emplace_back(i * length / elements_along_x, column_values[i]);
      return profile;
    }


    Profile
    profile_along_diagonal(const std::vector<double> &column_values,
                           const unsigned int         elements_along_x,
                           const unsigned int         elements_along_y,
                           const double               length,
                           const double               width)
    {
      const double hx  = length / elements_along_x;
      const double hy  = width / elements_along_y;
      const double end = std::min(length, width);

      // Crossings with the grid lines, merged where they coincide.
      std::vector<double> crossings;
      for (unsigned int i = 0; i <= elements_along_x; ++i)
        crossings.push_back(i * hx);
      for (unsigned int j = 0; j <= elements_along_y; ++j)
        crossings.push_back(j * hy);
      std::sort(crossings.begin(), crossings.end());
      const double tolerance = 1e-9 * std::min(hx, hy);
      crossings.erase(std::unique(crossings.begin(),
                                  crossings.end(),
                                  [&](const double a, const double b)
                                  { return std::abs(a - b) < tolerance; }),
                      crossings.end());

      const auto value = [&](const unsigned int i, const unsigned int j)
      { return column_values[i + j * (elements_along_x + 1)]; };
      Profile profile;
      for (const double x0 : crossings)
      {
        if (x0 > end + tolerance)
          break;
        const auto [i, xi]  = locate(x0, hx, elements_along_x);
        const auto [j, eta] = locate(x0, hy, elements_along_y);
        profile.emplace_back(std::sqrt(2.) * x0,
                             (1. - xi) * (1. - eta) * value(i, j)
                               + xi * (1. - eta) * value(i + 1, j)
                               + (1. - xi) * eta * value(i, j + 1)
                               + xi * eta * value(i + 1, j + 1));
      }
      return profile;
    }
  } // namespace problem
} // namespace deepdraw
