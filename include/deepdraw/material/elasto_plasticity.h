// Elastoplasticity at a material point (doc/theory_material.md): isotropic
// elasticity, a yield criterion (Hill'48 or Yld2004-18p), an isotropic
// hardening law (Swift, Voce or tabulated) and Prager kinematic hardening;
// fully implicit return mapping and its exact algorithmic tangent.
#ifndef deepdraw_material_elasto_plasticity_h
#define deepdraw_material_elasto_plasticity_h

#include <deal.II/base/symmetric_tensor.h>
#include <deepdraw/material/hardening_law.h>
#include <deepdraw/material/hill48_criterion.h>
#include <deepdraw/material/material_parameters.h>
#include <deepdraw/material/material_point_state.h>
#include <deepdraw/material/yld2004_criterion.h>

namespace deepdraw
{
  namespace material
  {
    class ElastoPlasticity
    {
    public:
      // Validates the parameters (throws InputError) and prepares the
      // criterion once (Hill'48: the spectral form of its tensor;
      // Yld2004-18p: the transformations and the normalisation).
      explicit ElastoPlasticity(const MaterialParameters &parameters);

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

      // Equivalent stress of xi = sigma - X under the selected criterion
      // (= the stress of uniaxial tension in the rolling direction).
      double
      equivalent_stress(const dealii::SymmetricTensor<2, 3> &xi) const;

      // Y(epbar) of the hardening law.
      double
      yield_stress(const double equivalent_plastic_strain) const;

      // dY/d epbar.
      double
      hardening_modulus(const double equivalent_plastic_strain) const;

      const dealii::SymmetricTensor<4, 3> &
      elasticity_tensor() const;

      // The two criteria (only the selected one is used by update()).
      const Hill48Criterion &
      hill48_criterion() const;

      const Yld2004Criterion &
      yld2004_criterion() const;

      const MaterialParameters &
      get_parameters() const;

    private:
      MaterialParameters parameters;

      double shear_modulus; // G
      double bulk_modulus;
      double lame_lambda;

      dealii::SymmetricTensor<4, 3> elasticity;
      Hill48Criterion               hill48;
      Yld2004Criterion              yld2004;
      HardeningLaw                  hardening;

      // The plastic corrector of each criterion, from the trial state
      // xi_trial = sigma_trial - X_n outside the yield surface
      // (sigma_bar_trial > Y_n). Same contract as update().
      bool
      return_mapping_hill48(const MaterialPointState            &old_state,
                            const dealii::SymmetricTensor<2, 3> &xi_trial,
                            const double                   sigma_bar_trial,
                            const double                   Y_n,
                            const double                   dY_n,
                            MaterialPointState            &new_state,
                            dealii::SymmetricTensor<4, 3> &tangent) const;

      bool
      return_mapping_general(const MaterialPointState            &old_state,
                             const dealii::SymmetricTensor<2, 3> &xi_trial,
                             MaterialPointState                  &new_state,
                             dealii::SymmetricTensor<4, 3> &tangent) const;
    };
  } // namespace material
} // namespace deepdraw

#endif
