// The quadrature of the selective reduced integration (doc/theory.md §3): the
// 2x2xn Gauss points carry the weights (n through the thickness, the cell's
// reference z, D202), a last point at the cell centre has weight zero
// (doc/theory.md §3). The hydrostatic part of the gradients is taken as the
// cell average of the Gauss-point gradients, which equals the centre gradient
// on parallelepipeds and, unlike it, passes the patch test on warped cells
// (doc/theory.md §3).
#ifndef deepdraw_fe_selective_reduced_quadrature_h
#define deepdraw_fe_selective_reduced_quadrature_h

#include <deal.II/base/quadrature.h>

namespace deepdraw
{
  namespace fe
  {
    using namespace dealii;

    // The most points through the thickness, and so the most weighted
    // points of a cell.
    constexpr unsigned int max_points_through_thickness = 4;
    constexpr unsigned int max_weighted_points
      = 4 * max_points_through_thickness;

    // 2 x 2 x points_through_thickness Gauss points (x fastest), then the
    // centre. 2 points give deal.II's QGauss<3>(2) as it is.
    Quadrature<3>
    selective_reduced_quadrature(unsigned int points_through_thickness);

    // Points that carry weight; the centre point follows them.
    inline unsigned int
    n_weighted_points(const Quadrature<3> &quadrature)
    {
      return quadrature.size() - 1;
    }

    // The points through the thickness of a rule with points_per_cell
    // weighted points (4 per point through the thickness).
    inline unsigned int
    points_through_thickness(const unsigned int points_per_cell)
    {
      return points_per_cell / 4;
    }

    // The rule whose cells carry points_per_cell weighted points (a state's
    // history). Throws if none does.
    Quadrature<3>
    quadrature_with_weighted_points(unsigned int points_per_cell);
  } // namespace fe
} // namespace deepdraw

#endif
