// Incremental objective kinematics of one increment [t, t+dt] (doc/theory.md
// §1-2): from the displacement-increment gradient H = grad_{x_t}(du) it
// computes the mid-increment velocity gradient dL = H F_half^{-1} (F_half = I +
// H/2), the strain increment d_eps = sym dL, the spin increment dW = skew dL
// and the Hughes-Winget rotation Q = (I - dW/2)^{-1} (I + dW/2), the half-step
// rotation Q_half = (I - dW/4)^{-1} (I + dW/4) that carries the material
// axes to the mid-increment configuration where d_eps is measured (their
// derivatives are taken in fe/quadrature_point_update.cc, doc/theory.md §4).
#ifndef deepdraw_kinematics_hughes_winget_increment_h
#define deepdraw_kinematics_hughes_winget_increment_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace deepdraw
{
  namespace kinematics
  {
    using namespace dealii;

    class HughesWingetIncrement
    {
    public:
      // Returns false if F = I + H is not invertible with det F > 0
      // (an inverted element: the caller cuts the increment).
      bool
      reinit(const Tensor<2, 3> &displacement_increment_gradient);

      Tensor<2, 3>          H;
      Tensor<2, 3>          deformation_gradient; // F = I + H
      Tensor<2, 3>          inverse_deformation_gradient;
      double                jacobian = 1.;
      Tensor<2, 3>          velocity_gradient_increment; // dL
      SymmetricTensor<2, 3> strain_increment;            // sym dL
      Tensor<2, 3>          spin_increment;              // skew dL
      Tensor<2, 3>          rotation;                    // Q
      Tensor<2, 3>          half_rotation;               // Q_half

    private:
      Tensor<2, 3> inverse_half_deformation_gradient; // F_half^{-1}
      Tensor<2, 3> inverse_a;                         // (I - dW/2)^{-1}
      Tensor<2, 3> inverse_a_half;                    // (I - dW/4)^{-1}
    };
  } // namespace kinematics
} // namespace deepdraw

#endif
