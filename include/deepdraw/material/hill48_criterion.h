// Hill'48 yield criterion (doc/theory_material.md §1.1): the equivalent
// stress sigma_bar^2 = xi : M : xi of the relative stress xi = sigma - X in
// the material frame, and the spectral form of M that the return mapping of
// ElastoPlasticity solves in closed form (§2).
#ifndef deepdraw_material_hill48_criterion_h
#define deepdraw_material_hill48_criterion_h

#include <deal.II/base/symmetric_tensor.h>
#include <deepdraw/material/material_parameters.h>

namespace deepdraw
{
  namespace material
  {
    class Hill48Criterion
    {
    public:
      // Spectral form of M in the Kelvin/Mandel basis, without the
      // hydrostatic mode (eigenvalue 0): two deviatoric modes of the normal
      // block (eigenvalues normal_eigenvalues, unit eigenvectors
      // normal_eigenvectors in (11, 22, 33)) and the shear modes 12, 13, 23
      // with eigenvalues N, M, L.
      struct Spectrum
      {
        double normal_eigenvalues[2];
        double normal_eigenvectors[2][3];
        double shear_eigenvalues[3];
        double smallest_eigenvalue;
      };

      // Builds M and diagonalises it once (parameters already validated).
      explicit Hill48Criterion(const MaterialParameters &parameters);

      // Hill'48 equivalent stress of xi = sigma - X.
      double
      equivalent_stress(const dealii::SymmetricTensor<2, 3> &xi) const;

      // M with sigma_bar^2 = xi : M : xi (full tensor contraction).
      const dealii::SymmetricTensor<4, 3> &
      tensor() const;

      const Spectrum &
      spectrum() const;

    private:
      double                        F, G, H, L, M, N;
      dealii::SymmetricTensor<4, 3> hill;
      Spectrum                      eigen;
    };
  } // namespace material
} // namespace deepdraw

#endif
