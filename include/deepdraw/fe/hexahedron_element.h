// The updated-Lagrangian 8-node hexahedron of the sheet: element residual and
// exact tangent for each element technology (doc/theory.md §3), with the
// enhanced parameters of the incompatible modes condensed inside the element.
//
// With dof i = (node a, component c) and enhanced parameter k = (mode m,
// component c), every column of the element is a gradient
//   G_j = e_c (x) v_j + beta_j I
// (v_j = g_a or the mode gradient g~_m; beta_j the mean-dilatation trace
// correction of a compatible column, 0 for a mode), H = sum_j x_j G_j, and
//   r_j = sum_q w_q G_j : P,   K_ij = sum_q w_q G_i : dP/dH : G_j.
// The enhanced rows r_alpha = 0 are solved in the element (local Newton) and
// condensed: K* = K_uu - K_ua K_aa^{-1} K_au, r* = r_u - K_ua K_aa^{-1} r_a.
#ifndef deepdraw_fe_hexahedron_element_h
#define deepdraw_fe_hexahedron_element_h

#include <array>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/full_matrix.h>
#include <deepdraw/fe/cell_geometry.h>
#include <deepdraw/fe/element_technology.h>
#include <deepdraw/fe/quadrature_point_update.h>

namespace deepdraw
{
  namespace fe
  {
    using namespace dealii;

    constexpr unsigned int dofs_per_cell = 24;
    // Nine parameters of the three Wilson-Taylor modes, three more for
    // each through-thickness mode (D202).
    constexpr unsigned int max_enhanced     = 3 * max_modes;
    constexpr unsigned int max_element_size = dofs_per_cell + max_enhanced;

    // The element-internal unknowns of one cell: part of the history
    // (committed with the quadrature points, restored on a cut-back).
    struct EnhancedParameters
    {
      // alpha of the current increment, alpha_{m,c} at [3 m + c]: the
      // enhanced part of grad_{x_t} du is sum_m alpha_m (x) g~_m.
      std::array<double, max_enhanced> values{};
      // The element's linearisation at its last evaluation, which predicts
      // alpha for the next displacement increment du:
      //   alpha(du) = values + correction + sensitivity (du - evaluated_at).
      std::array<double, dofs_per_cell>                evaluated_at{};
      std::array<double, max_enhanced>                 correction{};
      std::array<double, max_enhanced * dofs_per_cell> sensitivity{};

      // The start of an increment whose du is `ratio` times the last one
      // (0: from rest).
      void
      scale(double ratio);
    };

    enum class ElementStatus
    {
      ok,
      inverted,               // det F <= 0 at a point
      return_mapping_failed,  // the material's local Newton failed
      enhanced_not_converged, // the enhanced parameters did not converge
      // Not a failure: the local iterations were used up without meeting
      // the enhanced tolerance; the element's residual and tangent are
      // condensed at its last enhanced parameters, and the global Newton
      // iterates on (D189).
      enhanced_pending
    };

    class HexahedronElement
    {
    public:
      // fe: FESystem(FE_Q(1), 3), for the order of the local dofs.
      HexahedronElement(const ElementParameters          &parameters,
                        const material::ElastoPlasticity &material,
                        const FiniteElement<3>           &fe);

      // Condensed residual (24) and, if matrix != nullptr, tangent
      // (24 x 24) for the local displacement increments du (local dof
      // order of fe); old/trial: the cell's 8 quadrature points; enhanced
      // is read and updated (ignored without incompatible modes).
      ElementStatus
      evaluate(const CellGeometry           &geometry,
               const double                 *du,
               const QuadraturePointHistory *old_history,
               QuadraturePointHistory       *trial_history,
               EnhancedParameters           &enhanced,
               double                       *residual,
               FullMatrix<double>           *matrix,
               unsigned int                 &plastic_points) const;

    private:
      // One pass over the Gauss points at fixed alpha: residual (n = 24 +
      // n_enhanced) and, if tangents != nullptr, the material tangents
      // dP/dH of the 8 points times their weights (the matrix is built from
      // them by tangent_matrix, once the local Newton of alpha needs it).
      ElementStatus
      integrate(const CellGeometry           &geometry,
                const double                 *du,
                const double                 *alpha,
                const QuadraturePointHistory *old_history,
                QuadraturePointHistory       *trial_history,
                double                       *residual,
                Tensor<4, 3>                 *tangents,
                unsigned int                 &plastic_points) const;
      // K_ij = sum_q G_i : (w dP/dH)_q : G_j for i, j in [first, n) into
      // the n x n row-major matrix (the other entries untouched): first = 24
      // gives K_aa for the local Newton, 0 the whole matrix.
      void
      tangent_matrix(const CellGeometry &geometry,
                     const Tensor<4, 3> *tangents,
                     unsigned int        first,
                     double             *matrix) const;

      ElementParameters                 parameters;
      const material::ElastoPlasticity &material;
      unsigned int                      n_enhanced;
      bool                              mean_dilatation;
      // local dof i = component local_component[i] of node local_node[i]
      std::array<unsigned int, dofs_per_cell> local_component;
      std::array<unsigned int, dofs_per_cell> local_node;
    };
  } // namespace fe
} // namespace deepdraw

#endif
