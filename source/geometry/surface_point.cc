#include <cmath>
#include <deepdraw/geometry/surface_point.h>

namespace deepdraw::geometry
{
  dealii::Tensor<1, 3>
  unit_normal(const SurfacePoint &point)
  {
    const dealii::Tensor<1, 3> n
      = dealii::cross_product_3d(point.x_u, point.x_v);
    return n / n.norm();
  }

  SurfaceCurvature
  compute_curvature(const SurfacePoint &point)
  {
    SurfaceCurvature           result;
    const dealii::Tensor<1, 3> n = unit_normal(point);

    dealii::Tensor<2, 2> &a = result.metric;
    a[0][0]                 = point.x_u * point.x_u;
    a[0][1] = a[1][0] = point.x_u * point.x_v;
    a[1][1]           = point.x_v * point.x_v;

    dealii::Tensor<2, 2> &b = result.second_fundamental_form;
    b[0][0]                 = point.x_uu * n;
    b[0][1] = b[1][0] = point.x_uv * n;
    b[1][1]           = point.x_vv * n;

    const dealii::Tensor<2, 2> a_inverse = dealii::invert(a);
    // Contravariant base vectors a^a = a^ab x_b.
    const std::array<dealii::Tensor<1, 3>, 2> dual
      = {{a_inverse[0][0] * point.x_u + a_inverse[0][1] * point.x_v,
          a_inverse[1][0] * point.x_u + a_inverse[1][1] * point.x_v}};

    result.normal_gradient = 0;
    for (unsigned int alpha = 0; alpha < 2; ++alpha)
      for (unsigned int beta = 0; beta < 2; ++beta)
        result.normal_gradient
          -= b[alpha][beta] * dealii::outer_product(dual[alpha], dual[beta]);

    // Eigenvalues of the Weingarten matrix W = -a^-1 b (the map dn in the
    // basis x_u, x_v): kappa = H -/+ sqrt(D) with the discriminant written
    // as D = ((W00 - W11) / 2)^2 + W01 W10 rather than H^2 - K, which
    // cancels at umbilic points (spheres, planes).
    const dealii::Tensor<2, 2> weingarten = -a_inverse * b;
    const double mean            = 0.5 * (weingarten[0][0] + weingarten[1][1]);
    const double half_difference = 0.5 * (weingarten[0][0] - weingarten[1][1]);
    const double root
      = std::sqrt(std::max(half_difference * half_difference
                             + weingarten[0][1] * weingarten[1][0],
                           0.));
    result.principal_curvatures = {{mean - root, mean + root}};
    return result;
  }
} // namespace deepdraw::geometry
