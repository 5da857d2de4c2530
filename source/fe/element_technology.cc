#include <deepdraw/fe/element_technology.h>

namespace deepdraw
{
  namespace fe
  {
    std::string
    to_string(const ElementTechnology technology)
    {
      switch (technology)
      {
        case ElementTechnology::incompatible_modes:
          return "incompatible modes";
        case ElementTechnology::selective_reduced:
          return "selective reduced";
        case ElementTechnology::full:
          return "full";
      }
      return "unknown";
    }


    bool
    uses_mean_dilatation(const ElementTechnology technology)
    {
      // Incompatible modes: the modes carry the volumetric freedom; a
      // constant pressure per cell would lose the pressure varying through
      // each layer in elastic bending (doc/decisions.md D38).
      return technology == ElementTechnology::selective_reduced;
    }


    unsigned int
    n_enhanced_parameters(const ElementTechnology technology,
                          const unsigned int      points_through_thickness)
    {
      if (technology != ElementTechnology::incompatible_modes)
        return 0;
      // Three per mode: the Wilson-Taylor modes, and one through-thickness
      // mode per point through the thickness beyond 2 (D202).
      return 3 * (3 + points_through_thickness - 2);
    }


    void
    ElementParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Element",
        "incompatible modes",
        Patterns::Selection("incompatible modes|selective reduced|full"),
        "Element technology of the 8-node hexahedron (doc/theory.md §3). "
        "'incompatible modes': 2x2x2 Gauss integration with nine "
        "Wilson-Taylor incompatible modes (Simo-Armero enhanced gradient, "
        "condensed in the element): no shear, trapezoidal or volumetric "
        "locking in bending with one or more layers; use it for sheets. "
        "'selective reduced': mean dilatation only (the reference "
        "model's element; too stiff in bending unless the in-plane size is "
        "about the layer thickness). 'full': plain 2x2x2 Gauss integration "
        "(also locks under isochoric plastic flow; for comparison).");
      prm.declare_entry("Enhanced tolerance",
                        "1e-4",
                        Patterns::Double(1e-16, 1e-3),
                        "Incompatible modes: the element's enhanced "
                        "parameters are iterated until the largest enhanced "
                        "residual is below this fraction of the largest "
                        "nodal force of the element. The condensed residual "
                        "is corrected by the remaining enhanced step, so its "
                        "error is of the order of this tolerance squared.");
      prm.declare_entry("Enhanced iterations",
                        "25",
                        Patterns::Integer(1, 100),
                        "Incompatible modes: evaluations of the element "
                        "(Newton steps and their halvings) allowed for its "
                        "enhanced parameters before the attempt is cut "
                        "back (or, see Enhanced iterations exhausted, "
                        "before the global Newton takes over).");
      prm.declare_entry("Enhanced iterations exhausted",
                        "cut back",
                        Patterns::Selection("iterate globally|cut back"),
                        "Incompatible modes: what happens when an element "
                        "has used up its Enhanced iterations without "
                        "meeting the Enhanced tolerance. 'iterate "
                        "globally': it is condensed at its last enhanced "
                        "parameters (Simo-Rifai: the remaining step "
                        "corrects its residual) and the global Newton "
                        "goes on; an increment converges only when every "
                        "element meets the tolerance. 'cut back': the "
                        "attempt fails and the increment is cut back "
                        "(D189: the default, as no run was measured to "
                        "gain from the other).");
      prm.declare_entry(
        "Points through the thickness",
        "2",
        Patterns::Integer(2, 4),
        "Gauss points of each element through the sheet's thickness (its "
        "reference z direction), with 2 x 2 in the plane: 2, 3 or 4. With "
        "3 or 4 the incompatible-modes element adds one or two "
        "through-thickness modes (12 or 15 enhanced parameters), so that "
        "the transverse stress vanishes at every point. In plastic bending "
        "a layer's stress profile kinks at the edge of the elastic core, "
        "which 2 points a layer integrate with an error of a few per cent "
        "of the residual stress with few layers: the bent strip's residual "
        "stress with 4 layers is within 4.0 %, 2.1 % and 1.2 % of the "
        "closed form with 2, 3 and 4 points (D196, D202). For springback "
        "with 2 to 4 layers; the assembly costs about 1.6 or 2.2 times "
        "as much.");
    }


    void
    ElementParameters::parse_parameters(ParameterHandler &prm)
    {
      const std::string name  = prm.get("Element");
      technology              = name == "selective reduced"
                                  ? ElementTechnology::selective_reduced
                                : name == "full" ? ElementTechnology::full
                                                 : ElementTechnology::incompatible_modes;
      enhanced_tolerance      = prm.get_double("Enhanced tolerance");
      enhanced_max_iterations = prm.get_integer("Enhanced iterations");
      iterate_enhanced_globally
        = prm.get("Enhanced iterations exhausted") == "iterate globally";
      points_through_thickness
        = prm.get_integer("Points through the thickness");
    }
  } // namespace fe
} // namespace deepdraw
