#include <algorithm>
#include <cmath>
#include <deepdraw/material/hill48_criterion.h>

namespace deepdraw
{
  namespace material
  {
    Hill48Criterion::Hill48Criterion(const MaterialParameters &parameters)
        : F(parameters.hill_F)
        , G(parameters.hill_G)
        , H(parameters.hill_H)
        , L(parameters.hill_L)
        , M(parameters.hill_M)
        , N(parameters.hill_N)
    {
      // Hill tensor: normal block P (sigma_bar^2 = xi_n . P xi_n + ...), and
      // M_1212 = N/2 etc. because xi : M : xi counts xi_12 M_1212 xi_12 four
      // times (12 and 21 in both pairs): 4 (N/2) xi_12^2 = 2 N xi_12^2.
      const double P[3][3]
        = {{G + H, -H, -G}, {-H, F + H, -F}, {-G, -F, F + G}};
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          hill[i][i][j][j] = P[i][j];
      hill[0][1][0][1] = 0.5 * N;
      hill[0][2][0][2] = 0.5 * M;
      hill[1][2][1][2] = 0.5 * L;

      // Spectral form of M in the Kelvin basis. P (1,1,1) = 0 exactly, so the
      // hydrostatic mode has eigenvalue 0; the other two lie in the deviatoric
      // plane, spanned by d1 = (1,-1,0)/sqrt2, d2 = (1,1,-2)/sqrt6: diagonalise
      // the 2x2 projection of P there in closed form.
      const double d[2][3]
        = {{1. / std::sqrt(2.), -1. / std::sqrt(2.), 0.},
           {1. / std::sqrt(6.), 1. / std::sqrt(6.), -2. / std::sqrt(6.)}};
      double p[2][2];
      for (unsigned int a = 0; a < 2; ++a)
        for (unsigned int b = 0; b < 2; ++b)
        {
          p[a][b] = 0.;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              p[a][b] += d[a][i] * P[i][j] * d[b][j];
        }
      const double mean   = 0.5 * (p[0][0] + p[1][1]);
      const double radius = std::hypot(0.5 * (p[0][0] - p[1][1]), p[0][1]);
      const double theta  = 0.5 * std::atan2(2. * p[0][1], p[0][0] - p[1][1]);
      const double c = std::cos(theta), s = std::sin(theta);
      eigen.normal_eigenvalues[0] = mean + radius;
      eigen.normal_eigenvalues[1] = mean - radius;
      for (unsigned int i = 0; i < 3; ++i)
      {
        eigen.normal_eigenvectors[0][i] = c * d[0][i] + s * d[1][i];
        eigen.normal_eigenvectors[1][i] = -s * d[0][i] + c * d[1][i];
      }
      // Raw order of the shear entries: 12, 13, 23.
      eigen.shear_eigenvalues[0] = N;
      eigen.shear_eigenvalues[1] = M;
      eigen.shear_eigenvalues[2] = L;
      eigen.smallest_eigenvalue  = std::min({eigen.normal_eigenvalues[1],
                                             eigen.shear_eigenvalues[0],
                                             eigen.shear_eigenvalues[1],
                                             eigen.shear_eigenvalues[2]});
    }


    double
    Hill48Criterion::equivalent_stress(
      const dealii::SymmetricTensor<2, 3> &xi) const
    {
      const double d23 = xi[1][1] - xi[2][2], d31 = xi[2][2] - xi[0][0],
                   d12 = xi[0][0] - xi[1][1];
      const double q   = F * d23 * d23 + G * d31 * d31 + H * d12 * d12
                       + 2.
                           * (L * xi[1][2] * xi[1][2] + M * xi[0][2] * xi[0][2]
                              + N * xi[0][1] * xi[0][1]);
      return std::sqrt(std::max(q, 0.));
    }


    const dealii::SymmetricTensor<4, 3> &
    Hill48Criterion::tensor() const
    {
      return hill;
    }


    const Hill48Criterion::Spectrum &
    Hill48Criterion::spectrum() const
    {
      return eigen;
    }
  } // namespace material
} // namespace deepdraw
