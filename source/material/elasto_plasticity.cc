#include <cmath>
#include <deepdraw/material/elasto_plasticity.h>

namespace deepdraw
{
  namespace material
  {
    using dealii::SymmetricTensor;

    namespace
    {
      // The criteria are built from validated parameters only.
      const MaterialParameters &
      validated(const MaterialParameters &parameters)
      {
        parameters.validate();
        return parameters;
      }

      // Elastic if sigma_bar_trial - Y_n <= this * Y_n
      // (doc/theory_material.md §2).
      constexpr double yield_tolerance = 1e-12;
    } // namespace


    ElastoPlasticity::ElastoPlasticity(const MaterialParameters &parameters)
        : parameters(validated(parameters))
        , hill48(parameters)
        , yld2004(parameters)
        , hardening(parameters)
    {
      const double E  = parameters.youngs_modulus;
      const double nu = parameters.poissons_ratio;
      shear_modulus   = E / (2. * (1. + nu));
      lame_lambda     = E * nu / ((1. + nu) * (1. - 2. * nu));
      bulk_modulus    = E / (3. * (1. - 2. * nu));

      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          elasticity[i][i][j][j]
            = lame_lambda + (i == j ? 2. * shear_modulus : 0.);
      elasticity[0][1][0][1] = elasticity[0][2][0][2] = elasticity[1][2][1][2]
        = shear_modulus;
    }


    double
    ElastoPlasticity::equivalent_stress(const SymmetricTensor<2, 3> &xi) const
    {
      return parameters.yield_criterion == YieldCriterion::hill48
               ? hill48.equivalent_stress(xi)
               : yld2004.equivalent_stress(xi);
    }


    double
    ElastoPlasticity::yield_stress(const double equivalent_plastic_strain) const
    {
      return hardening.yield_stress(equivalent_plastic_strain);
    }


    double
    ElastoPlasticity::hardening_modulus(
      const double equivalent_plastic_strain) const
    {
      return hardening.hardening_modulus(equivalent_plastic_strain);
    }


    const SymmetricTensor<4, 3> &
    ElastoPlasticity::elasticity_tensor() const
    {
      return elasticity;
    }


    const Hill48Criterion &
    ElastoPlasticity::hill48_criterion() const
    {
      return hill48;
    }


    const Yld2004Criterion &
    ElastoPlasticity::yld2004_criterion() const
    {
      return yld2004;
    }


    const MaterialParameters &
    ElastoPlasticity::get_parameters() const
    {
      return parameters;
    }


    bool
    ElastoPlasticity::update(const MaterialPointState    &old_state,
                             const SymmetricTensor<2, 3> &strain_increment,
                             MaterialPointState          &new_state,
                             SymmetricTensor<4, 3>       &consistent_tangent,
                             bool                        &plastic) const
    {
      const double mu = shear_modulus;

      // Elastic predictor: sigma_trial = sigma_n + C : d_eps.
      const double          volumetric = lame_lambda * trace(strain_increment);
      SymmetricTensor<2, 3> stress_trial = old_state.stress;
      for (unsigned int I = 0; I < 6; ++I)
        stress_trial.access_raw_entry(I)
          += 2. * mu * strain_increment.access_raw_entry(I)
             + (I < 3 ? volumetric : 0.);
      const SymmetricTensor<2, 3> xi_trial
        = stress_trial - old_state.back_stress;

      const double sigma_bar_trial = equivalent_stress(xi_trial);
      double       Y_n, dY_n;
      hardening.evaluate(old_state.equivalent_plastic_strain, Y_n, dY_n);
      plastic = false;
      if (!std::isfinite(sigma_bar_trial) || !std::isfinite(Y_n))
        return false;

      if (sigma_bar_trial - Y_n <= yield_tolerance * Y_n)
      {
        new_state.stress      = stress_trial;
        new_state.back_stress = old_state.back_stress;
        new_state.equivalent_plastic_strain
          = old_state.equivalent_plastic_strain;
        consistent_tangent = elasticity;
        return true;
      }
      plastic = true;
      if (parameters.yield_criterion == YieldCriterion::hill48)
        return return_mapping_hill48(old_state,
                                     xi_trial,
                                     sigma_bar_trial,
                                     Y_n,
                                     dY_n,
                                     new_state,
                                     consistent_tangent);
      return return_mapping_general(old_state,
                                    xi_trial,
                                    new_state,
                                    consistent_tangent);
    }
  } // namespace material
} // namespace deepdraw
