// The sections of a strip bent about the y axis (tests/element/
// plastic_bending.cc, tests/springback/bent_strip_release.cc): the current
// positions of the vertices on y = 0 by their initial (x, z), a section's
// rotation, and the curvature between two sections.
#ifndef deepdraw_tests_element_strip_sections_h
#define deepdraw_tests_element_strip_sections_h

#include "contact/forming_test_tools.h"

#include <cmath>
#include <map>
#include <utility>

namespace bending_reference
{
  using namespace dealii;

  class StripSections
  {
  public:
    StripSections(const deepdraw::problem::FormingProblem &problem,
                  const double                             thickness)
        : thickness(thickness)
    {
      const auto &X = problem.access().sheet().initial_vertices();
      const auto &u = problem.access().state().total_displacement;
      forming_test::for_each_vertex(
        problem,
        [&](const auto &cell, const unsigned int v, const unsigned int vertex)
        {
          Point<3> x = X[vertex];
          for (unsigned int c = 0; c < 3; ++c)
            x[c] += u[cell->vertex_dof_index(v, c)];
          if (std::abs(X[vertex][1]) < 1e-9)
            position[{std::lround(X[vertex][0] * 1e3),
                      std::lround(X[vertex][2] * 1e3)}]
              = x;
        });
    }

    // The rotation of the section at initial x0 (mm; from z towards x) and
    // its mid-point.
    double
    rotation(const double x0, Point<3> &middle) const
    {
      const Point<3> &bottom = position.at({std::lround(x0 * 1e3), 0});
      const Point<3> &top
        = position.at({std::lround(x0 * 1e3), std::lround(thickness * 1e3)});
      middle = 0.5 * (bottom + top);
      return std::atan2(top[0] - bottom[0], top[2] - bottom[2]);
    }

    // The rotation of the sections x_a and x_b over the arc of a circle
    // through their mid-points with that angle.
    double
    curvature(const double x_a, const double x_b) const
    {
      Point<3>     middle_a, middle_b;
      const double angle = rotation(x_b, middle_b) - rotation(x_a, middle_a);
      return angle
             / (middle_a.distance(middle_b) * (0.5 * angle)
                / std::sin(0.5 * angle));
    }

  private:
    double                                    thickness;
    std::map<std::pair<long, long>, Point<3>> position;
  };
} // namespace bending_reference

#endif
