#include <deal.II/base/symmetric_tensor.h>
#include <deepdraw/contact/contact_pair.h>

namespace deepdraw
{
  namespace contact
  {
    ContactPairResult
    open_contact_pair(const dealii::Tensor<1, 3> &multiplier,
                      const double                augmentation,
                      const double                normal_gap)
    {
      ContactPairResult result;
      result.state               = ContactState::open;
      result.constraint_residual = multiplier / augmentation;
      result.dconstraint_dmultiplier
        = dealii::Tensor<2, 3>(dealii::unit_symmetric_tensor<3>())
          / augmentation;
      result.normal_gap = normal_gap;
      return result;
    }


    ContactPairResult
    evaluate_contact_pair(const AlartCurnierLaw       &law,
                          const ContactPairKinematics &kinematics,
                          const dealii::Tensor<1, 3>  &multiplier,
                          const double                 augmentation)
    {
      const AlartCurnierResponse  response = law.evaluate(multiplier,
                                                         kinematics.gap(),
                                                         kinematics.normal(),
                                                         augmentation);
      const dealii::Tensor<2, 3> &dg_du    = kinematics.dgap_ddisplacement();
      const dealii::Tensor<1, 3> &dg_dz    = kinematics.dgap_dtool_position();
      const dealii::Tensor<2, 3> &dn_du    = kinematics.dnormal_ddisplacement();
      const dealii::Tensor<1, 3> &dn_dz = kinematics.dnormal_dtool_position();

      ContactPairResult result;
      result.state               = response.state;
      result.force               = response.force;
      result.constraint_residual = response.constraint_residual;

      result.dforce_ddisplacement
        = response.dforce_dgap * dg_du + response.dforce_dnormal * dn_du;
      result.dforce_dmultiplier = response.dforce_dmultiplier;
      result.dforce_dtool_position
        = response.dforce_dgap * dg_dz + response.dforce_dnormal * dn_dz;

      result.dconstraint_ddisplacement = response.dconstraint_dgap * dg_du
                                         + response.dconstraint_dnormal * dn_du;
      result.dconstraint_dmultiplier = response.dconstraint_dmultiplier;
      result.dconstraint_dtool_position
        = response.dconstraint_dgap * dg_dz
          + response.dconstraint_dnormal * dn_dz;

      const dealii::Tensor<1, 3> &n = kinematics.normal();
      result.normal_gap             = kinematics.normal_gap();
      result.normal_force           = response.force * n;
      result.friction_force         = response.force - result.normal_force * n;
      return result;
    }
  } // namespace contact
} // namespace deepdraw
