// The square-cup builder with Plan corner radius = Half width (D76): round
// punch, die opening and holder contour for the cylindrical cup. Every
// point of every patch (a 9 x 9 grid of parameters) must lie on the exact
// surface of revolution (punch face z = z0 inside the face radius, nose
// torus of radius rp about the circle rho = Rp - rp, wall rho = Rp; die face
// z = 0 outside the shoulder, shoulder torus, wall rho = Rd), with the unit
// normal towards the sheet; tolerance 1e-12 mm (the rational arcs are
// exact, round-off only). The quarter disc of the punch face has 3
// patches, the nose and the wall one each; the die ring 2, shoulder and
// wall one each; the holder 2.
#include "test_utilities.h"

#include <cmath>
#include <deepdraw/geometry/square_cup_tools.h>
#include <functional>
#include <string>

using namespace dealii;
using namespace deepdraw::geometry;
using namespace deepdraw_test;

namespace
{
  // Largest |distance to the exact surface| and smallest normal . expected
  // normal over a tool's patches.
  void
  check_tool(const RigidTool   &tool,
             const std::string &name,
             const std::function<double(const Point<3> &, Tensor<1, 3> &)>
               &distance_and_normal)
  {
    double worst = 0., worst_normal = 1.;
    for (const BezierPatch &patch : tool.patches())
      for (unsigned int i = 0; i <= 8; ++i)
        for (unsigned int j = 0; j <= 8; ++j)
        {
          const Point<3> x = patch.value(i / 8., j / 8.);
          Tensor<1, 3>   expected_normal;
          worst = std::max(worst,
                           std::abs(distance_and_normal(x, expected_normal)));
          if (expected_normal.norm() > 0.)
            worst_normal
              = std::min(worst_normal,
                         patch.unit_normal(i / 8., j / 8.) * expected_normal);
        }
    check_close(name + ": largest distance to the exact surface",
                worst,
                0.,
                1e-12);
    check_close(name + ": normals towards the sheet (smallest n . n_exact)",
                worst_normal,
                1.,
                1e-12);
  }

  // Distance of x from the torus of tube radius r about the circle
  // rho = a, z = c; n: the unit normal out of the tube times sign.
  double
  torus_distance(const Point<3> &x,
                 const double    a,
                 const double    c,
                 const double    r,
                 const double    sign,
                 Tensor<1, 3>   &n)
  {
    const double       rho = std::hypot(x[0], x[1]);
    const double       dr = rho - a, dz = x[2] - c;
    const Tensor<1, 3> out({dr * x[0] / rho, dr * x[1] / rho, dz});
    n = sign * out / out.norm();
    return out.norm() - r;
  }
} // namespace


int
main()
{
  SquareCupToolParameters p;
  p.punch_half_width       = 48.73;
  p.punch_corner_radius    = 48.73;
  p.punch_profile_radius   = 12.7;
  p.die_opening_half_width = 50.74;
  p.die_corner_radius      = 50.74;
  p.die_shoulder_radius    = 12.7;
  const double t           = 0.81;
  const auto   tools       = build_square_cup_tools(p, t);
  check_true("punch 5, die 4, holder 2 patches",
             tools[0].n_patches() == 5 && tools[1].n_patches() == 4
               && tools[2].n_patches() == 2);

  const double Rp = p.punch_half_width, rp = p.punch_profile_radius;
  check_tool(tools[0],
             "punch",
             [&](const Point<3> &x, Tensor<1, 3> &n)
             {
               const double       rho = std::hypot(x[0], x[1]);
               const double       z0  = t;
               const Tensor<1, 3> radial({x[0] / rho, x[1] / rho, 0.});
               if (std::abs(x[2] - z0) < 1e-9 && rho <= Rp - rp + 1e-9)
               {
                 n = Tensor<1, 3>({0., 0., -1.});
                 return x[2] - z0;
               }
               if (x[2] <= z0 + rp)
               {
                 // Nose: the torus about rho = Rp - rp, z = z0 + rp.
                 return torus_distance(x, Rp - rp, z0 + rp, rp, 1., n);
               }
               n = radial;
               return rho - Rp;
             });
  const double Rd = p.die_opening_half_width, rd = p.die_shoulder_radius;
  check_tool(tools[1],
             "die",
             [&](const Point<3> &x, Tensor<1, 3> &n)
             {
               const double       rho = std::hypot(x[0], x[1]);
               const Tensor<1, 3> radial({x[0] / rho, x[1] / rho, 0.});
               if (std::abs(x[2]) < 1e-9 && rho >= Rd + rd - 1e-9)
               {
                 n = Tensor<1, 3>({0., 0., 1.});
                 return x[2];
               }
               if (x[2] >= -rd)
               {
                 // Shoulder: the torus about rho = Rd + rd, z = -rd; the
                 // die fills the tube, the sheet is outside it.
                 return torus_distance(x, Rd + rd, -rd, rd, 1., n);
               }
               n = -radial;
               return rho - Rd;
             });
  check_tool(tools[2],
             "blank holder",
             [&](const Point<3> &x, Tensor<1, 3> &n)
             {
               n = Tensor<1, 3>({0., 0., -1.});
               // Flat at z = t outside the circle rho = Rd + rd.
               const double rho = std::hypot(x[0], x[1]);
               return std::abs(x[2] - t) + std::max(0., Rd + rd - rho - 1e-9);
             });
  return summary();
}
