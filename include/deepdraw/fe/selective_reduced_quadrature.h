// The quadrature of the selective reduced integration (doc/theory.md §3): the
// 2x2x2 Gauss points carry the weights, a ninth point at the cell centre has
// weight zero (doc/theory.md §3). The hydrostatic part of the gradients is
// taken as the cell average of the Gauss-point gradients, which equals the
// centre gradient on parallelepipeds and, unlike it, passes the patch test on
// warped cells (doc/theory.md §3).
#ifndef deepdraw_fe_selective_reduced_quadrature_h
#define deepdraw_fe_selective_reduced_quadrature_h

#include <deal.II/base/quadrature.h>

namespace deepdraw
{
  namespace fe
  {
    using namespace dealii;

    // Number of points that carry weight; the centre point follows them.
    constexpr unsigned int n_weighted_points = 8;

    Quadrature<3>
    selective_reduced_quadrature();
  } // namespace fe
} // namespace deepdraw

#endif
