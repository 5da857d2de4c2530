// The curve of subsection Formability (doc/theory_formability.md §2, D133).
#include <cmath>
#include <deepdraw/formability/forming_limit_curve_factory.h>
#include <deepdraw/formability/keeler_brazier_flc.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/value_check.h>

namespace deepdraw
{
  namespace formability
  {
    TabulatedFlc
    marciniak_kuczynski_curve(const PlaneStressYield             &yield,
                              const material::MaterialParameters &material,
                              const MarciniakKuczynskiParameters &parameters,
                              const std::string                  &yield_name)
    {
      const MkHardening        hardening(material);
      const MarciniakKuczynski mk(yield, hardening, parameters);
      std::vector<FlcPoint>    points;
      for (const MkLimitPoint &limit : mk.limit_curve())
        points.push_back({limit.minor_strain,
                          limit.major_strain,
                          limit.strain_ratio,
                          limit.groove_angle});
      // Kinematic hardening is left out of the analysis (D135): said where
      // the curve is described (--flc prints it, the plots' titles show it).
      const std::string kinematic
        = material.prager_modulus != 0.
            ? "; isotropic hardening and proportional loading assumed, "
              "Material/Prager modulus = "
                + io::number_text(material.prager_modulus) + " MPa ignored"
            : "";
      const std::string description
        = "Marciniak-Kuczynski, " + yield_name + ", " + hardening.description()
          + ", f0 = " + io::number_text(parameters.imperfection) + kinematic;
      return TabulatedFlc(points,
                          "the Marciniak-Kuczynski curve (strain ratios "
                          "from the uniaxial one to 1)",
                          description);
    }


    std::unique_ptr<FormingLimitCurve>
    create_forming_limit_curve(const FormabilityParameters        &parameters,
                               const material::MaterialParameters &material,
                               const double sheet_thickness)
    {
      using CurveType = FormabilityParameters::CurveType;
      switch (parameters.curve_type)
      {
        case CurveType::none:
          return nullptr;
        case CurveType::tabulated:
          return std::make_unique<TabulatedFlc>(parameters.table,
                                                parameters.table_source,
                                                "tabulated ("
                                                  + parameters.table_source
                                                  + ")");
        case CurveType::keeler_brazier:
        {
          const bool n_given = !std::isnan(parameters.keeler_n);
          const bool t_given = !std::isnan(parameters.keeler_thickness);
          if (!n_given
              && material.hardening_law != material::HardeningLawType::swift)
            throw InputError(
              "Formability/Keeler-Brazier n is empty and Material/Hardening "
              "law is not Swift: there is no Swift exponent to take n from; "
              "allowed values: a number 0 < n <= 0.21 (the sheet's "
              "hardening exponent)");
          return std::make_unique<KeelerBrazierFlc>(
            n_given ? parameters.keeler_n : material.swift_exponent,
            t_given ? parameters.keeler_thickness : sheet_thickness,
            n_given ? "Formability/Keeler-Brazier n"
                    : "Material/Swift exponent",
            t_given ? "Formability/Keeler-Brazier thickness"
                    : "Geometry/Thickness");
        }
        case CurveType::marciniak_kuczynski:
          return std::make_unique<TabulatedFlc>(
            marciniak_kuczynski_curve(*create_plane_stress_yield(material),
                                      material,
                                      parameters.marciniak_kuczynski,
                                      plane_stress_yield_name(material)));
      }
      return nullptr;
    }


    std::unique_ptr<FormingLimitCurve>
    create_required_forming_limit_curve(
      const FormabilityParameters        &parameters,
      const material::MaterialParameters &material,
      const double                        sheet_thickness)
    {
      std::unique_ptr<FormingLimitCurve> curve
        = create_forming_limit_curve(parameters, material, sheet_thickness);
      if (curve == nullptr)
        throw InputError("Formability/Forming limit curve is none: there is "
                         "no curve to write; allowed values are tabulated, "
                         "Keeler-Brazier and Marciniak-Kuczynski");
      return curve;
    }
  } // namespace formability
} // namespace deepdraw
