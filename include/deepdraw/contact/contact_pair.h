// One contact pair (sheet node, rigid tool) evaluated for the global Newton
// step: the Alart–Curnier law composed with the pair kinematics, giving the
// residual contributions and the blocks of reference Eq. (19).
#ifndef deepdraw_contact_contact_pair_h
#define deepdraw_contact_contact_pair_h

#include <deal.II/base/tensor.h>
#include <deepdraw/contact/alart_curnier_law.h>
#include <deepdraw/contact/contact_pair_kinematics.h>

namespace deepdraw
{
  namespace contact
  {
    // Residuals and total derivatives of one pair with respect to the node's
    // displacement increment Δu, its multiplier λ and the tool position z.
    // How the solver uses them, per node and tool:
    //   equilibrium row of the node:  f_int(Δu) − P − f_ext = 0,
    //     so K_uu −= dP/dΔu, K_uλ = −dP/dλ, K_uz = −dP/dz;
    //   multiplier rows:              F_sup = 0,
    //     K_λu = dF_sup/dΔu, K_λλ = dF_sup/dλ, K_λz = dF_sup/dz;
    //   blank holder row (force control): −Σ_nodes a·P = prescribed force
    //     along a (reaction of the sheet on the holder), derivatives
    //     −a·dP/d(·).
    struct ContactPairResult
    {
      ContactState state = ContactState::open;

      // P, the force of the tool on the node, and F_sup = (λ − P)/r.
      dealii::Tensor<1, 3> force;
      dealii::Tensor<1, 3> constraint_residual;

      dealii::Tensor<2, 3> dforce_ddisplacement;
      dealii::Tensor<2, 3> dforce_dmultiplier;
      dealii::Tensor<1, 3> dforce_dtool_position;
      dealii::Tensor<2, 3> dconstraint_ddisplacement;
      dealii::Tensor<2, 3> dconstraint_dmultiplier;
      dealii::Tensor<1, 3> dconstraint_dtool_position;

      // For output: g_N, normal force P·n (>= 0) and friction force
      // P − (P·n) n.
      double               normal_gap   = 0;
      double               normal_force = 0;
      dealii::Tensor<1, 3> friction_force;
    };

    // An open pair (beyond the search distance, or on the law's open branch
    // with the tool's derivatives all zero): P = 0, F_sup = λ/r,
    // dF_sup/dλ = I/r; normal_gap for the output.
    ContactPairResult
    open_contact_pair(const dealii::Tensor<1, 3> &multiplier,
                      double                      augmentation,
                      double                      normal_gap);

    // Chain rule: d(·)/dΔu = ∂(·)/∂ĝ dĝ/dΔu + ∂(·)/∂n dn/dΔu, same for z.
    ContactPairResult
    evaluate_contact_pair(const AlartCurnierLaw       &law,
                          const ContactPairKinematics &kinematics,
                          const dealii::Tensor<1, 3>  &multiplier,
                          const double                 augmentation);
  } // namespace contact
} // namespace deepdraw

#endif
