// The forming-limit curve that a parsed subsection Formability describes
// (doc/theory_formability.md §2, D133): for the FLD post-processor and for
// deepdraw --flc. All input errors are InputError, raised before anything
// is written.
#ifndef deepdraw_formability_forming_limit_curve_factory_h
#define deepdraw_formability_forming_limit_curve_factory_h

#include <deepdraw/formability/formability_parameters.h>
#include <deepdraw/formability/tabulated_flc.h>
#include <deepdraw/material/material_parameters.h>
#include <memory>

namespace deepdraw
{
  namespace formability
  {
    // nullptr for curve type none. sheet_thickness (mm, Geometry/Thickness)
    // is the Keeler-Brazier thickness when that entry is empty, and the
    // Swift exponent of material its n (InputError for another hardening
    // law); the M-K curve uses the yield criterion of material in plane
    // stress (create_plane_stress_yield) and its hardening law
    // (MkHardening).
    std::unique_ptr<FormingLimitCurve>
    create_forming_limit_curve(const FormabilityParameters        &parameters,
                               const material::MaterialParameters &material,
                               double sheet_thickness);

    // The same, but InputError for curve type none: for a command that
    // exists to write the curve (deepdraw --flc).
    std::unique_ptr<FormingLimitCurve>
    create_required_forming_limit_curve(
      const FormabilityParameters        &parameters,
      const material::MaterialParameters &material,
      double                              sheet_thickness);

    // The M-K limit points of every strain ratio as a tabulated curve
    // (with their strain ratios and critical groove angles), for any
    // plane-stress yield function and the hardening law of material.
    TabulatedFlc
    marciniak_kuczynski_curve(const PlaneStressYield             &yield,
                              const material::MaterialParameters &material,
                              const MarciniakKuczynskiParameters &parameters,
                              const std::string &yield_name = "Hill'48");
  } // namespace formability
} // namespace deepdraw

#endif
