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
  } // namespace kinematics
} // namespace deepdraw
