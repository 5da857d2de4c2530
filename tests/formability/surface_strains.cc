// Surface strains are exact for homogeneous deformations, in the current
// tangent plane: each case maps the corners of a face by x = F X + c with
// a known F and compares with its known principal stretches (ln lambda) and
// major direction. Uniaxial (lambda, 1/sqrt lambda), plane strain,
// equibiaxial, a rigid rotation of the sheet into a vertical wall (zero
// strains), a face that is stretched along an oblique direction and turned
// into an inclined plane, an irregular (non-parallelogram) face, and the
// four children of a refined face (the same strains on a refined mesh).
// Measured 3.6e-16 at most (round-off): 2e-15 allowed.
#include "../test_utilities.h"

#include <deal.II/base/symmetric_tensor.h>
#include <deepdraw/formability/surface_strain.h>

using namespace deepdraw;
using dealii::Point;
using dealii::Tensor;
using Corners = std::array<Point<3>, 4>;

namespace
{
  Corners
  mapped(const Corners &X, const Tensor<2, 3> &F, const Tensor<1, 3> &c)
  {
    Corners x;
    for (unsigned int k = 0; k < 4; ++k)
      x[k] = Point<3>(F * X[k] + c);
    return x;
  }

  // Rotation by angle about the unit axis (Rodrigues).
  Tensor<2, 3>
  rotation(const Tensor<1, 3> &axis, const double angle)
  {
    Tensor<2, 3> R;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        R[i][j] = std::cos(angle) * (i == j)
                  + (1. - std::cos(angle)) * axis[i] * axis[j];
    R[0][1] -= std::sin(angle) * axis[2];
    R[1][0] += std::sin(angle) * axis[2];
    R[0][2] += std::sin(angle) * axis[1];
    R[2][0] -= std::sin(angle) * axis[1];
    R[1][2] -= std::sin(angle) * axis[0];
    R[2][1] += std::sin(angle) * axis[0];
    return R;
  }

  void
  check(const std::string  &what,
        const Corners      &X,
        const Tensor<2, 3> &F,
        const double        major,
        const double        minor,
        const Tensor<1, 3> &direction,
        const Tensor<1, 3> &normal)
  {
    const Tensor<1, 3>               shift({3., -2., 7.});
    const formability::SurfaceStrain s
      = formability::surface_strain(X, mapped(X, F, shift));
    deepdraw_test::check_close(what + ": major", s.major_strain, major, 2e-15);
    deepdraw_test::check_close(what + ": minor", s.minor_strain, minor, 2e-15);
    if (direction.norm() > 0.)
      deepdraw_test::check_close(what + ": |major direction . expected|",
                                 std::abs(s.major_direction * direction),
                                 1.,
                                 2e-15);
    deepdraw_test::check_close(what + ": |normal . expected|",
                               std::abs(s.normal * normal),
                               1.,
                               2e-15);
  }
} // namespace


int
main()
{
  const Corners      square = {{Point<3>(0, 0, 0),
                                Point<3>(2, 0, 0),
                                Point<3>(0, 2, 0),
                                Point<3>(2, 2, 0)}};
  const Tensor<1, 3> x({1., 0., 0.}), y({0., 1., 0.}), z({0., 0., 1.});
  const double       l = 1.3;

  Tensor<2, 3> F;
  F[0][0] = l, F[1][1] = 1. / std::sqrt(l), F[2][2] = 1. / std::sqrt(l);
  check("uniaxial", square, F, std::log(l), -0.5 * std::log(l), x, z);

  F       = Tensor<2, 3>();
  F[0][0] = 1.2, F[1][1] = 1., F[2][2] = 1. / 1.2;
  check("plane strain", square, F, std::log(1.2), 0., x, z);

  F       = Tensor<2, 3>();
  F[0][0] = F[1][1] = 1.15, F[2][2] = 1. / (1.15 * 1.15);
  check("equibiaxial", square, F, std::log(1.15), std::log(1.15), {}, z);

  // Into a vertical wall: rotated by 90 degrees about x, the sheet lies in
  // the x-z plane with normal -y.
  check("rigid rotation into a wall",
        square,
        rotation(x, M_PI / 2.),
        0.,
        0.,
        {},
        y);

  // Stretched by 1.25 along d (30 degrees in the sheet) and by 0.9 across,
  // then turned by 50 degrees about an oblique axis.
  const double       a = M_PI / 6.;
  const Tensor<1, 3> d({std::cos(a), std::sin(a), 0.});
  const Tensor<1, 3> e({-std::sin(a), std::cos(a), 0.});
  const Tensor<2, 3> U = 1.25 * outer_product(d, d) + 0.9 * outer_product(e, e)
                         + outer_product(z, z);
  Tensor<1, 3> axis({1., 2., 2.});
  axis /= axis.norm();
  const Tensor<2, 3> R = rotation(axis, 50. * M_PI / 180.);
  // The same stretch in the plane that Q turns the x-y plane into, then
  // turned by R.
  const auto oblique
    = [&](const std::string &what, const Corners &X, const Tensor<2, 3> &Q)
  {
    check(what,
          X,
          R * Q * U * transpose(Q),
          std::log(1.25),
          std::log(0.9),
          R * Q * d,
          R * Q * z);
  };
  const Tensor<2, 3> I = dealii::unit_symmetric_tensor<3>();
  oblique("stretched and rotated face", square, I);

  // An irregular face of an unstructured blank, in an inclined plane.
  const Tensor<2, 3> tilt = rotation(y, 0.4);
  Corners            irregular;
  const double corners[4][2] = {{0., 0.}, {1.7, 0.2}, {-0.3, 1.1}, {1.2, 1.6}};
  for (unsigned int k = 0; k < 4; ++k)
    irregular[k]
      = Point<3>(tilt * Tensor<1, 3>({corners[k][0], corners[k][1], 0.}));
  oblique("irregular inclined face", irregular, tilt);

  // The four children of the square (a refined face, hanging nodes on its
  // edges): the same strains in each.
  for (unsigned int child = 0; child < 4; ++child)
  {
    const Tensor<1, 3> offset({1. * (child % 2), 1. * (child / 2), 0.});
    Corners            small;
    for (unsigned int k = 0; k < 4; ++k)
      small[k] = Point<3>(0.5 * square[k] + offset);
    oblique("child " + std::to_string(child), small, I);
  }
  return deepdraw_test::summary();
}
