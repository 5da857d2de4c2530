// Hanging-node constraints of the vector Q1 element FESystem(FE_Q(1), 3) on
// hexahedral meshes with isotropic and anisotropic refinement (doc/theory.md
// §8): deal.II 9.4 stops with "not implemented" on anisotropically refined
// faces of this element. On a Q1 mesh every hanging vertex is the midpoint of
// a refined edge of a coarser active cell (constrained to the two ends, 1/2
// each) or the centre of an isotropically refined face (to its four
// vertices, 1/4 each); deeper levels are chains that close() resolves.
#ifndef deepdraw_fe_hanging_node_constraints_h
#define deepdraw_fe_hanging_node_constraints_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

namespace deepdraw
{
  namespace fe
  {
    using namespace dealii;

    // Adds the constraints of every hanging vertex to constraints (lines
    // already present are left alone); does not close them. The DoFHandler
    // must use FE_Q(1) or FESystem(FE_Q(1), n).
    void
    make_q1_hanging_node_constraints(const DoFHandler<3>       &dof_handler,
                                     AffineConstraints<double> &constraints);
  } // namespace fe
} // namespace deepdraw

#endif
