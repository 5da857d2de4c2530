// Kelvin (Mandel) coordinates of symmetric tensors: the six raw entries of
// dealii::SymmetricTensor<2,3> (11, 22, 33, 12, 13, 23) with the shear ones
// times sqrt2, so that a : b is the dot product and fourth-order tensors
// with the minor symmetries are symmetric 6 x 6 matrices
// (doc/theory_material.md §2). Small fixed-size helpers for the general
// return mapping; nothing allocates.
#ifndef deepdraw_material_kelvin_h
#define deepdraw_material_kelvin_h

#include <array>
#include <cmath>
#include <deal.II/base/symmetric_tensor.h>

namespace deepdraw
{
  namespace material
  {
    namespace kelvin
    {
      using Vector = std::array<double, 6>;
      using Matrix = std::array<Vector, 6>;

      // Weight of raw entry I: 1 for the normal, sqrt2 for the shear ones.
      inline double
      weight(const unsigned int I)
      {
        return I < 3 ? 1. : std::sqrt(2.);
      }

      inline Vector
      from_tensor(const dealii::SymmetricTensor<2, 3> &t)
      {
        Vector v;
        for (unsigned int I = 0; I < 6; ++I)
          v[I] = weight(I) * t.access_raw_entry(I);
        return v;
      }

      inline dealii::SymmetricTensor<2, 3>
      to_tensor(const Vector &v)
      {
        dealii::SymmetricTensor<2, 3> t;
        for (unsigned int I = 0; I < 6; ++I)
          t.access_raw_entry(I) = v[I] / weight(I);
        return t;
      }

      // The tensor T_ijkl whose Kelvin matrix is m (raw entry (I,J) of the
      // 6 x 6 array at 6 I + J holds T_ijkl itself).
      inline void
      to_tensor(const Matrix &m, dealii::SymmetricTensor<4, 3> &t)
      {
        for (unsigned int I = 0; I < 6; ++I)
          for (unsigned int J = 0; J < 6; ++J)
            t.access_raw_entry(6 * I + J) = m[I][J] / (weight(I) * weight(J));
      }

      inline double
      dot(const Vector &a, const Vector &b)
      {
        double s = 0.;
        for (unsigned int I = 0; I < 6; ++I)
          s += a[I] * b[I];
        return s;
      }

      // Cholesky factor L (lower triangle, A = L L^T) of a symmetric
      // positive definite A in place; false if a pivot is not positive.
      inline bool
      cholesky(Matrix &a)
      {
        for (unsigned int j = 0; j < 6; ++j)
        {
          double d = a[j][j];
          for (unsigned int k = 0; k < j; ++k)
            d -= a[j][k] * a[j][k];
          if (!(d > 0.))
            return false;
          a[j][j] = std::sqrt(d);
          for (unsigned int i = j + 1; i < 6; ++i)
          {
            double s = a[i][j];
            for (unsigned int k = 0; k < j; ++k)
              s -= a[i][k] * a[j][k];
            a[i][j] = s / a[j][j];
          }
        }
        return true;
      }

      // x = A^{-1} b from the Cholesky factor of A.
      inline Vector
      solve(const Matrix &l, const Vector &b)
      {
        Vector x;
        for (unsigned int i = 0; i < 6; ++i)
        {
          double s = b[i];
          for (unsigned int k = 0; k < i; ++k)
            s -= l[i][k] * x[k];
          x[i] = s / l[i][i];
        }
        for (int i = 5; i >= 0; --i)
        {
          double s = x[i];
          for (unsigned int k = i + 1; k < 6; ++k)
            s -= l[k][i] * x[k];
          x[i] = s / l[i][i];
        }
        return x;
      }
    } // namespace kelvin
  }   // namespace material
} // namespace deepdraw

#endif
