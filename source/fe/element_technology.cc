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
    n_enhanced_parameters(const ElementTechnology technology)
    {
      return technology == ElementTechnology::incompatible_modes ? 9 : 0;
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
    }
  } // namespace fe
} // namespace deepdraw
