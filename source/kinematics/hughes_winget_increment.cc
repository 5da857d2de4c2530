#include <deepdraw/kinematics/hughes_winget_increment.h>

namespace deepdraw
{
  namespace kinematics
  {
    bool
    HughesWingetIncrement::reinit(
      const Tensor<2, 3> &displacement_increment_gradient)
    {
      const Tensor<2, 3> identity = unit_symmetric_tensor<3>();
      H                           = displacement_increment_gradient;
      deformation_gradient        = identity + H;
      jacobian                    = determinant(deformation_gradient);
      if (!(jacobian > 0.))
        return false;
      inverse_deformation_gradient = invert(deformation_gradient);

      const Tensor<2, 3> half_deformation_gradient = identity + 0.5 * H;
      const double       half_jacobian = determinant(half_deformation_gradient);
      if (!(half_jacobian > 0.))
        return false;
      inverse_half_deformation_gradient = invert(half_deformation_gradient);

      velocity_gradient_increment = H * inverse_half_deformation_gradient;
      strain_increment            = symmetrize(velocity_gradient_increment);
      spin_increment              = 0.5
                       * (velocity_gradient_increment
                          - transpose(velocity_gradient_increment));
      // Q = (I - dW/2)^{-1}(I + dW/2): orthogonal for any skew dW.
      inverse_a      = invert(identity - 0.5 * spin_increment);
      rotation       = inverse_a * (identity + 0.5 * spin_increment);
      inverse_a_half = invert(identity - 0.25 * spin_increment);
      half_rotation  = inverse_a_half * (identity + 0.25 * spin_increment);
      return true;
    }


    void
    HughesWingetIncrement::variation(const Tensor<2, 3> &dH,
                                     Tensor<2, 3>       &d_strain_increment,
                                     Tensor<2, 3>       &d_spin_increment,
                                     Tensor<2, 3>       &d_rotation,
                                     Tensor<2, 3>       &d_half_rotation) const
    {
      const Tensor<2, 3> identity = unit_symmetric_tensor<3>();
      // d(dL) = (I - dL/2) dH F_half^{-1}
      const Tensor<2, 3> d_velocity_gradient
        = (identity - 0.5 * velocity_gradient_increment) * dH
          * inverse_half_deformation_gradient;
      d_strain_increment
        = 0.5 * (d_velocity_gradient + transpose(d_velocity_gradient));
      d_spin_increment
        = 0.5 * (d_velocity_gradient - transpose(d_velocity_gradient));
      // dQ = A^{-1} (d dW / 2) (I + Q), A = I - dW/2
      d_rotation = 0.5 * inverse_a * d_spin_increment * (identity + rotation);
      d_half_rotation
        = 0.25 * inverse_a_half * d_spin_increment * (identity + half_rotation);
    }
  } // namespace kinematics
} // namespace deepdraw
