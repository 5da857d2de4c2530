// Hertz line contact of a rigid cylinder on an elastic block (issue 4,
// test 4), run from data/hertz_cylinder.prm (also the benchmark case).
//
// A rigid cylinder, R = 50 mm, written as one quadratic rational Bézier
// patch (data/hertz_cylinder.tool, weights 1, sqrt(2)/2, 1: an exact
// circle), is pressed frictionlessly into an elastic block in plane strain
// (uy = 0 on both y faces). For a rigid cylinder on an elastic half-space
// (Johnson, Contact Mechanics, §4.2, Eqs. 4.43, 4.45), with F' the force
// per unit length and E* = E / (1 - nu^2):
//   a  = sqrt(4 F' R / (pi E*)),   p(x) = p0 sqrt(1 - x^2/a^2),
//   p0 = 2 F' / (pi a).
// F' is measured (the sum of the nodal contact forces of the half model,
// doubled, over the width); a and p0 then follow from the formulas and are
// compared with the discrete solution:
//  - half-width from the second moment of the pressure, which for the
//    Hertz distribution is int p x^2 / int p = a^2 / 4: a_h = 2 sqrt(sum f_i
//    x_i^2 / sum f_i) with the nodal forces f_i (the hat functions
//    interpolate x^2 to O(h^2), a bias of h^2/(4 a^2) ~ 0.3 % here). This
//    uses the whole distribution rather than the last node in contact,
//    which resolves a only to one element (10 %);
//  - the extent of the contact zone: the last node carrying force must lie
//    within one element h of a;
//  - peak pressure: the nodal force at x = 0 over its tributary area
//    (h/2 x width/2 per node: symmetry plane and block edge).
// Tolerance 1 % for a and p0 (the issue allowed 10 %): measured 0.44 %
// (a from the second moment) and 0.31 % (p0), so about 2.5 and 3 times
// what is reached. The deviations have known sources of that size: the
// block is finite (5 x 5 mm, a ~ 1 mm, on a frictionless support), the
// mesh has h = a/10 (second-moment bias h^2/(4 a^2) ~ 0.3 %), the nodal
// pressure at the peak is a hat-weighted average of p over [0, h]
// (-0.2 %), and strains ~ a/(2R) = 1 % add geometric nonlinearity.
// Also: all contact force is normal (frictionless): |friction| ~ 0. The
// normals tilt by x/R <= 2 %: the sum of the nodal normal forces exceeds
// the tool force along z by the mean of x^2/(2R^2), measured 4.2e-5,
// asserted to 1e-4; summed with cos(theta), sin(theta) = x/R at the
// node's current x, it equals the tool force to round-off (measured
// 1.4e-16, asserted 1e-12): the contact normals are radial through the
// nodes.
#include "forming_test_tools.h"

#include <deal.II/base/mpi.h>
#include <map>

using namespace dealii;
using namespace deepdraw;
using deepdraw_test::check_close;
using deepdraw_test::check_relative;
using deepdraw_test::check_true;

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // Must match data/hertz_cylinder.prm and data/hertz_cylinder.tool.
  const double E = 71000., nu = 0.3, R = 50.;
  const double thickness = 5., width = 0.1, h = 0.1;
  const double E_star = E / (1. - nu * nu);

  const auto problem
    = forming_test::run_from_file("hertz_cylinder.prm", "hertz_cylinder");
  const auto nodal = problem->access().contact().nodal_contact(
    problem->access().sheet().initial_vertices().size());
  const auto &X = problem->access().sheet().initial_vertices();

  // Line load per node column x_i (sum over the two nodes along y).
  std::map<long, std::pair<double, double>> columns; // i -> (x_i, f_i)
  double                                    max_friction = 0.;
  for (const unsigned int v :
       forming_test::vertices_on_plane(*problem, 2, thickness))
  {
    const long   i = std::lround(X[v][0] / h);
    const double x
      = X[v][0] + forming_test::vertex_displacement(*problem, v)[0];
    columns[i].first = x;
    columns[i].second += nodal[v].normal_force;
    max_friction = std::max(max_friction, nodal[v].friction_force.norm());
  }
  double sum_f = 0., sum_fx2 = 0., sum_fz = 0., f_max = 0., x_last = 0.;
  for (const auto &[i, column] : columns)
  {
    sum_f += column.second;
    sum_fx2 += column.second * column.first * column.first;
    // z component of a normal force at x on the cylinder: cos(theta),
    // sin(theta) = x / R.
    sum_fz
      += column.second * std::sqrt(1. - column.first * column.first / (R * R));
    f_max = std::max(f_max, column.second);
  }
  for (const auto &[i, column] : columns)
    if (column.second > 1e-8 * f_max)
      x_last = std::max(x_last, column.first);

  const double       F_line = 2. * sum_f / width; // full cylinder, N/mm
  const double       a    = std::sqrt(4. * F_line * R / (numbers::PI * E_star));
  const double       p0   = 2. * F_line / (numbers::PI * a);
  const double       a_h  = 2. * std::sqrt(sum_fx2 / sum_f);
  const double       p0_h = columns[0].second / (0.5 * h * width);
  const Tensor<1, 3> tool_force = problem->access().contact().tool_forces()[0];

  std::cout << "F' = " << F_line << " N/mm; Hertz a = " << a
            << " mm, p0 = " << p0 << " MPa" << std::endl
            << "computed: a (second moment) = " << a_h
            << " mm, last node in contact x = " << x_last
            << " mm, p(0) = " << p0_h << " MPa" << std::endl
            << "nodal pressures (x, p):";
  for (const auto &[i, column] : columns)
    if (column.first <= 1.5 * a)
      std::cout << " (" << column.first << ", "
                << column.second / ((i == 0 ? 0.5 : 1.) * h * width) << ")";
  std::cout << std::endl;

  check_relative("sum of nodal normal forces vs tool Fz",
                 sum_f,
                 -tool_force[2],
                 1e-4);
  check_relative("sum of z components of the nodal normal forces vs tool Fz",
                 sum_fz,
                 -tool_force[2],
                 1e-12);
  check_true("contact half-width around 1 mm (a/R = 2 %, a/h = 10)",
             a > 0.7 && a < 1.3);
  check_relative("half-width from the second moment vs Hertz a", a_h, a, 1e-2);
  check_close("last node in contact vs Hertz a (one element)", x_last, a, h);
  check_relative("peak pressure p(0) vs Hertz p0", p0_h, p0, 1e-2);
  check_close("max |friction force| (frictionless)",
              max_friction,
              0.,
              1e-8 * f_max);
  return deepdraw_test::summary();
}
