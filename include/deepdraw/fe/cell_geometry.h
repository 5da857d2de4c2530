// What the element needs of a cell's shape in the configuration x_t: computed
// once per increment, after the mesh has moved (doc/theory.md §1, §3).
#ifndef deepdraw_fe_cell_geometry_h
#define deepdraw_fe_cell_geometry_h

#include <array>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_values.h>
#include <vector>

namespace deepdraw
{
  namespace fe
  {
    using namespace dealii;

    // Incompatible modes per cell: the three Wilson-Taylor modes, and the
    // through-thickness modes of rules with 3 points through the thickness
    // (one, quadratic) or 4 (two, quadratic and cubic) (D202).
    constexpr unsigned int max_modes = 5;

    struct CellGeometry
    {
      // Gradients wrt x_t of the 8 scalar shape functions at the weighted
      // Gauss points, [q * 8 + a].
      std::vector<Tensor<1, 3>> gradient;
      // Their volume average (1/V) int grad N_a dV: the constant
      // volumetric gradient of the mean dilatation.
      std::array<Tensor<1, 3>, 8> mean_gradient;
      // Gradients of the incompatible modes at the Gauss points,
      // [q * max_modes + m]: (j0 / j) J0^{-T} xi_m e_m (Taylor's form), then
      // the through-thickness modes' (j0 / j) J0^{-T} P(xi_z) e_z; their
      // volume integrals vanish, so constant stress gives no enhanced force.
      std::vector<Tensor<1, 3>> mode_gradient;
      // One per weighted Gauss point (8, 12 or 16, D202).
      std::vector<double> JxW;

      unsigned int
      n_points() const
      {
        return JxW.size();
      }
    };

    // fe_values: a scalar FE_Q(1) on the selective reduced quadrature
    // (the weighted Gauss points + centre), reinit'ed on the cell, with
    // gradients, JxW values and Jacobians.
    void
    compute_cell_geometry(const FEValues<3> &fe_values, CellGeometry &geometry);

    // The update flags compute_cell_geometry needs.
    inline UpdateFlags
    cell_geometry_flags()
    {
      return update_gradients | update_JxW_values | update_jacobians;
    }
  } // namespace fe
} // namespace deepdraw

#endif
