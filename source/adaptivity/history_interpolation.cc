#include <algorithm>
#include <cmath>
#include <deepdraw/adaptivity/history_interpolation.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <stdexcept>

namespace deepdraw
{
  namespace adaptivity
  {
    Tensor<2, 3>
    nearest_rotation(const Tensor<2, 3> &A)
    {
      // Newton's iteration for the polar factor converges quadratically
      // from a matrix near a rotation (Higham, Functions of Matrices, §8.3).
      Tensor<2, 3> R = A;
      for (unsigned int iteration = 0; iteration < 50; ++iteration)
      {
        const Tensor<2, 3> next   = 0.5 * (R + transpose(invert(R)));
        const double       change = (next - R).norm();
        R                         = next;
        if (change < 1e-15)
          break;
      }
      return R;
    }


    std::vector<double>
    interpolation_weights(const Quadrature<3> &quadrature, const Point<3> &xi)
    {
      // Per direction, linear between the two of the rule's coordinates
      // that bracket xi (the outer two beyond them); the weighted points
      // come first, the selective reduced rule appends the centre.
      const unsigned int  n = fe::n_weighted_points(quadrature);
      std::vector<double> weights(n, 1.);
      for (unsigned int d = 0; d < 3; ++d)
      {
        std::vector<double> coordinates;
        for (unsigned int q = 0; q < n; ++q)
          coordinates.push_back(quadrature.point(q)[d]);
        std::sort(coordinates.begin(), coordinates.end());
        coordinates.erase(std::unique(coordinates.begin(), coordinates.end()),
                          coordinates.end());
        std::size_t k = 0;
        while (k + 2 < coordinates.size() && xi[d] > coordinates[k + 1])
          ++k;
        const double low = coordinates[k], high = coordinates[k + 1];
        for (unsigned int q = 0; q < n; ++q)
        {
          const double c = quadrature.point(q)[d];
          weights[q] *= c == high  ? (xi[d] - low) / (high - low)
                        : c == low ? (high - xi[d]) / (high - low)
                                   : 0.;
        }
      }
      return weights;
    }


    fe::QuadraturePointHistory
    interpolate_history(const fe::QuadraturePointHistory *parent,
                        const Quadrature<3>              &quadrature,
                        const Point<3>                   &xi,
                        const material::ElastoPlasticity &material)
    {
      const std::vector<double>  w = interpolation_weights(quadrature, xi);
      fe::QuadraturePointHistory result;
      result.state.stress                    = 0;
      result.state.back_stress               = 0;
      result.state.equivalent_plastic_strain = 0.;
      Tensor<2, 3> axes;
      for (unsigned int q = 0; q < w.size(); ++q)
      {
        // Stress and back stress in the material frame (σ̂, X̂): the
        // co-rotated fields, smooth where the sheet bends.
        result.state.stress += w[q] * parent[q].state.stress;
        result.state.back_stress += w[q] * parent[q].state.back_stress;
        result.state.equivalent_plastic_strain
          += w[q] * parent[q].state.equivalent_plastic_strain;
        axes += w[q] * parent[q].material_axes;
      }
      result.material_axes = nearest_rotation(axes);
      result.state.equivalent_plastic_strain
        = std::max(0., result.state.equivalent_plastic_strain);

      // Back onto the yield surface, radially in the deviatoric plane.
      const SymmetricTensor<2, 3> xi_stress
        = result.state.stress - result.state.back_stress;
      const double equivalent = material.equivalent_stress(xi_stress);
      const double yield
        = material.yield_stress(result.state.equivalent_plastic_strain);
      if (equivalent > yield)
      {
        const SymmetricTensor<2, 3> deviatoric = deviator(xi_stress);
        result.state.stress                    = result.state.back_stress
                              + (xi_stress - deviatoric)
                              + (yield / equivalent) * deviatoric;
      }
      return result;
    }
  } // namespace adaptivity
} // namespace deepdraw
