// The element technologies of the sheet's 8-node hexahedron, chosen in
// `subsection Finite element` (doc/theory.md §3, doc/decisions.md D38).
#ifndef deepdraw_fe_element_technology_h
#define deepdraw_fe_element_technology_h

#include <deal.II/base/parameter_handler.h>
#include <string>

namespace deepdraw
{
  namespace fe
  {
    using namespace dealii;

    enum class ElementTechnology
    {
      // 2x2x2 Gauss integration with the nine Wilson-Taylor incompatible
      // modes (Simo-Armero enhanced gradient): no shear, trapezoidal or
      // volumetric locking in bending.
      incompatible_modes,
      // Mean-dilatation volumetric part only (the reference model's
      // element; locks in bending).
      selective_reduced,
      // Plain 2x2x2 Gauss integration (locks volumetrically and in
      // bending; for comparison).
      full
    };

    // The name used in the prm file.
    std::string
    to_string(ElementTechnology technology);

    // Whether the hydrostatic part of the compatible gradient is the cell
    // average (mean dilatation).
    bool
    uses_mean_dilatation(ElementTechnology technology);

    // Enhanced (element-internal) parameters per cell: 9, 12 or 15 with
    // 2, 3 or 4 points through the thickness (D202), or 0.
    unsigned int
    n_enhanced_parameters(ElementTechnology technology,
                          unsigned int      points_through_thickness);

    struct ElementParameters
    {
      ElementTechnology technology = ElementTechnology::incompatible_modes;
      // Local Newton of the enhanced parameters: converged when the
      // largest enhanced residual is below this fraction of the largest
      // nodal force of the element.
      double       enhanced_tolerance      = 1e-4;
      unsigned int enhanced_max_iterations = 25;
      // When they are used up: the element is condensed at its last
      // enhanced parameters and the global Newton goes on, converging only
      // once every element meets the tolerance (true); or the attempt is
      // cut back (false, the default, D189).
      bool iterate_enhanced_globally = false;
      // Gauss points through the thickness (reference z), 2 x 2 in the
      // plane (fe::selective_reduced_quadrature, D202).
      unsigned int points_through_thickness = 2;

      // Entries of `subsection Finite element` (the caller enters it).
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace fe
} // namespace deepdraw

#endif
