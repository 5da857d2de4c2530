// History of one material point, all tensors in the material (orthotropy)
// frame (doc/theory.md §1-2): the solver rotates in and out with R.
#ifndef deepdraw_material_material_point_state_h
#define deepdraw_material_material_point_state_h

#include <deal.II/base/symmetric_tensor.h>

namespace deepdraw
{
  namespace material
  {
    struct MaterialPointState
    {
      dealii::SymmetricTensor<2, 3> stress;      // Cauchy stress, MPa
      dealii::SymmetricTensor<2, 3> back_stress; // X, MPa
      double                        equivalent_plastic_strain = 0.;
    };
  } // namespace material
} // namespace deepdraw

#endif
