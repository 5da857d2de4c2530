// Hill'48 elastoplasticity with Swift isotropic and Prager kinematic
// hardening at a material point (doc/theory_material.md): fully implicit return
// mapping and its exact algorithmic tangent. Theory: doc/theory_material.md.
#ifndef deepdraw_material_hill_plasticity_h
#define deepdraw_material_hill_plasticity_h

#include <deal.II/base/symmetric_tensor.h>
#include <deepdraw/material/material_parameters.h>
#include <deepdraw/material/material_point_state.h>

namespace deepdraw
{
  namespace material
  {
    class HillPlasticity
    {
    public:
      // Validates the parameters (throws InputError) and diagonalises the
      // Hill tensor once.
      explicit HillPlasticity(const MaterialParameters &parameters);

      // Fully implicit return mapping (closest point projection) for the
      // strain increment given in the material frame (1 = rolling,
      // 2 = transverse, 3 = normal). Fills new_state and the consistent
      // (algorithmic) tangent d(stress_{n+1})/d(strain_increment); plastic
      // tells whether the step was plastic. Returns false if the local
      // Newton iteration fails (the caller then cuts the increment); the
      // outputs are then unusable. Thread-safe, no heap allocation.
      bool
      update(const MaterialPointState            &old_state,
             const dealii::SymmetricTensor<2, 3> &strain_increment,
             MaterialPointState                  &new_state,
             dealii::SymmetricTensor<4, 3>       &consistent_tangent,
             bool                                &plastic) const;

      // Hill'48 equivalent stress of xi = sigma - X.
      double
      equivalent_stress(const dealii::SymmetricTensor<2, 3> &xi) const;

      // Swift: Y = C (eps0 + epbar)^n.
      double
      yield_stress(const double equivalent_plastic_strain) const;

      // dY/d epbar.
      double
      hardening_modulus(const double equivalent_plastic_strain) const;

      const dealii::SymmetricTensor<4, 3> &
      elasticity_tensor() const;

      // M with sigma_bar^2 = xi : M : xi (full tensor contraction).
      const dealii::SymmetricTensor<4, 3> &
      hill_tensor() const;

      const MaterialParameters &
      get_parameters() const;

    private:
      MaterialParameters parameters;

      double shear_modulus; // G
      double bulk_modulus;
      double lame_lambda;

      dealii::SymmetricTensor<4, 3> elasticity;
      dealii::SymmetricTensor<4, 3> hill;

      // Spectral form of M in the Kelvin/Mandel basis, without the
      // hydrostatic mode (eigenvalue 0): two deviatoric modes of the normal
      // block (eigenvalues normal_eigenvalues, unit eigenvectors
      // normal_eigenvectors in (11, 22, 33)) and the shear modes 12, 13, 23
      // with eigenvalues N, M, L.
      double normal_eigenvalues[2];
      double normal_eigenvectors[2][3];
      double shear_eigenvalues[3];
      double smallest_eigenvalue;

      // Y and dY/d epbar with one pow().
      void
      swift(const double epbar, double &Y, double &dY) const;
    };
  } // namespace material
} // namespace deepdraw

#endif
