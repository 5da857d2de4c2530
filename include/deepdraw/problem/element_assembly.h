// The sheet's elements assembled into the Newton system (doc/theory.md §3):
// residual and exact tangent of every cell through fe::HexahedronElement,
// on all cores (WorkStream), added in a fixed cell order so that the
// results do not depend on the thread count (D61).
#ifndef deepdraw_problem_element_assembly_h
#define deepdraw_problem_element_assembly_h

#include <deepdraw/discretisation/sheet_discretisation.h>
#include <deepdraw/fe/hexahedron_element.h>
#include <deepdraw/fe/quadrature_point_update.h>
#include <deepdraw/linear_algebra/system_matrix.h>
#include <vector>

namespace deepdraw
{
  namespace problem
  {
    using namespace dealii;

    struct ElementAssemblyResult
    {
      // The most specific failure of a point (ok if none failed).
      fe::ElementStatus status         = fe::ElementStatus::ok;
      unsigned int      plastic_points = 0;
      // Elements condensed with unconverged enhanced parameters (D189).
      unsigned int pending_elements = 0;
    };

    // Adds the residual r (rhs -= r) of every cell this rank evaluates
    // and, with matrix != nullptr, its tangent for the displacement
    // increment du (which must satisfy the hanging-node constraints)
    // through the constraints; internal_force gets f_int, condensed onto
    // the masters of hanging vertices. The
    // trial history and element-internal unknowns are updated from the
    // committed history; all three hold the rank's own cells in their
    // order (sheet.owned_cells(), D217).
    ElementAssemblyResult
    assemble_elements(const fe::HexahedronElement               &element,
                      const discretisation::SheetDiscretisation &sheet,
                      const linear_algebra::Vector              &du,
                      const AffineConstraints<double>           &constraints,
                      const std::vector<fe::QuadraturePointHistory> &history,
                      std::vector<fe::QuadraturePointHistory> &trial_history,
                      std::vector<fe::EnhancedParameters>     &trial_enhanced,
                      linear_algebra::SystemMatrix            *matrix,
                      linear_algebra::Vector                  &rhs,
                      linear_algebra::Vector                  &internal_force);
  } // namespace problem
} // namespace deepdraw

#endif
