#include <algorithm>
#include <cmath>
#include <deal.II/base/tensor.h>
#include <deepdraw/process/rigid_body_modes.h>

namespace deepdraw
{
  namespace process
  {
    namespace
    {
      using Matrix6 = std::array<std::array<double, 6>, 6>;

      // Eigenvalues (diagonal of a) and eigenvectors (columns of v) of the
      // symmetric a by cyclic Jacobi rotations; 6 x 6 converges in a few
      // sweeps.
      void
      symmetric_eigenvectors(Matrix6 &a, Matrix6 &v)
      {
        for (unsigned int i = 0; i < 6; ++i)
          for (unsigned int j = 0; j < 6; ++j)
            v[i][j] = i == j ? 1. : 0.;
        for (unsigned int sweep = 0; sweep < 50; ++sweep)
        {
          double off = 0., diagonal = 0.;
          for (unsigned int i = 0; i < 6; ++i)
          {
            diagonal += a[i][i] * a[i][i];
            for (unsigned int j = i + 1; j < 6; ++j)
              off += a[i][j] * a[i][j];
          }
          if (off <= 1e-30 * diagonal)
            return;
          for (unsigned int p = 0; p < 6; ++p)
            for (unsigned int q = p + 1; q < 6; ++q)
            {
              if (a[p][q] == 0.)
                continue;
              const double theta = 0.5 * (a[q][q] - a[p][p]) / a[p][q];
              const double t
                = (theta >= 0. ? 1. : -1.)
                  / (std::abs(theta) + std::sqrt(theta * theta + 1.));
              const double c = 1. / std::sqrt(t * t + 1.), s = t * c;
              for (unsigned int k = 0; k < 6; ++k)
              {
                const double akp = a[k][p], akq = a[k][q];
                a[k][p] = c * akp - s * akq;
                a[k][q] = s * akp + c * akq;
              }
              for (unsigned int k = 0; k < 6; ++k)
              {
                const double apk = a[p][k], aqk = a[q][k];
                a[p][k] = c * apk - s * aqk;
                a[q][k] = s * apk + c * aqk;
              }
              for (unsigned int k = 0; k < 6; ++k)
              {
                const double vkp = v[k][p], vkq = v[k][q];
                v[k][p] = c * vkp - s * vkq;
                v[k][q] = s * vkp + c * vkq;
              }
            }
        }
      }
    } // namespace


    void
    RigidBodyModes::hold(const Point<3> &point, const unsigned int component)
    {
      held.emplace_back(point, component);
    }


    std::vector<std::string>
    RigidBodyModes::free_modes() const
    {
      Point<3> centre;
      for (const auto &[point, component] : held)
        centre += point / double(held.size());
      double extent = 0.;
      for (const auto &[point, component] : held)
        extent = std::max(extent, point.distance(centre));
      if (!(extent > 0.))
        extent = 1.;

      // Gram matrix of the rows [e_c, (X - X0)/L x e_c].
      Matrix6 gram{};
      for (const auto &[point, component] : held)
      {
        Tensor<1, 3> e;
        e[component]                 = 1.;
        const Tensor<1, 3>    arm    = (point - centre) / extent;
        const Tensor<1, 3>    moment = cross_product_3d(arm, e);
        std::array<double, 6> row{};
        for (unsigned int d = 0; d < 3; ++d)
        {
          row[d]     = e[d];
          row[3 + d] = moment[d];
        }
        for (unsigned int i = 0; i < 6; ++i)
          for (unsigned int j = 0; j < 6; ++j)
            gram[i][j] += row[i] * row[j];
      }
      Matrix6 vectors;
      symmetric_eigenvectors(gram, vectors);
      double largest = 0.;
      for (unsigned int i = 0; i < 6; ++i)
        largest = std::max(largest, gram[i][i]);

      // A mode is free where its eigenvalue is zero to the rounding of the
      // sums (the rows are of order 1).
      std::vector<std::string> modes;
      for (unsigned int m = 0; m < 6; ++m)
        if (!(gram[m][m] > 1e-10 * std::max(largest, 1.)))
        {
          unsigned int main_part = 0;
          for (unsigned int i = 1; i < 6; ++i)
            if (std::abs(vectors[i][m]) > std::abs(vectors[main_part][m]))
              main_part = i;
          modes.push_back((main_part < 3 ? std::string("translation along ")
                                         : std::string("rotation about "))
                          + "xyz"[main_part % 3]);
        }
      std::sort(modes.begin(), modes.end());
      modes.erase(std::unique(modes.begin(), modes.end()), modes.end());
      return modes;
    }
  } // namespace process
} // namespace deepdraw
