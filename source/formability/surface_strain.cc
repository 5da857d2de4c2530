// Principal surface strains (doc/theory_formability.md §1).
#include <cmath>
#include <deepdraw/formability/surface_strain.h>
#include <limits>

namespace deepdraw
{
  namespace formability
  {
    using dealii::Tensor;

    SurfaceStrain
    surface_strain(const std::array<Tensor<1, 3>, 2> &A,
                   const std::array<Tensor<1, 3>, 2> &a)
    {
      SurfaceStrain result;
      // Orthonormal basis of the initial tangent plane (Gram-Schmidt):
      // A_1 = |A_1| E_1, A_2 = c E_1 + d E_2; then f_k = F E_k follows from
      // a_k = F A_k by linearity.
      const double       length = A[0].norm();
      const double       c      = A[1] * A[0] / length;
      const double       d      = (A[1] - c / length * A[0]).norm();
      const Tensor<1, 3> normal = cross_product_3d(a[0], a[1]);
      if (!(d > 1e-12 * A[1].norm()) || !(normal.norm() > 0.))
      {
        result.major_strain = result.minor_strain
          = std::numeric_limits<double>::quiet_NaN();
        return result;
      }
      const Tensor<1, 3> f1 = a[0] / length;
      const Tensor<1, 3> f2 = (a[1] - c * f1) / d;
      // C = F^T F in (E_1, E_2): [[p, q], [q, r]].
      const double p = f1 * f1, q = f1 * f2, r = f2 * f2;
      const double mean    = 0.5 * (p + r);
      const double radius  = std::sqrt(0.25 * (p - r) * (p - r) + q * q);
      const double largest = mean + radius;
      // lambda_2^2 = det C / lambda_1^2 avoids the cancellation of
      // mean - radius.
      const double smallest = (p * r - q * q) / largest;
      result.major_strain   = 0.5 * std::log(largest);
      result.minor_strain   = 0.5 * std::log(smallest);
      // Lagrangian direction N = (cos t, sin t), tan 2t = 2q / (p - r); the
      // current one is F N / lambda_1.
      const double       angle = 0.5 * std::atan2(2. * q, p - r);
      const Tensor<1, 3> n     = std::cos(angle) * f1 + std::sin(angle) * f2;
      result.major_direction   = n / n.norm();
      result.normal            = normal / normal.norm();
      return result;
    }


    SurfaceStrain
    surface_strain(const std::array<dealii::Point<3>, 4> &X,
                   const std::array<dealii::Point<3>, 4> &x)
    {
      // d/d xi and d/d eta of the bilinear map at (1/2, 1/2).
      const auto tangents = [](const std::array<dealii::Point<3>, 4> &v)
      {
        return std::array<Tensor<1, 3>, 2>{
          {0.5 * ((v[1] - v[0]) + (v[3] - v[2])),
           0.5 * ((v[2] - v[0]) + (v[3] - v[1]))}};
      };
      return surface_strain(tangents(X), tangents(x));
    }
  } // namespace formability
} // namespace deepdraw
