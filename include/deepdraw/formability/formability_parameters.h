// Subsection Formability (doc/user_guide.md §8, doc/theory_formability.md):
// which forming-limit curve, its inputs, the safety band and the thresholds
// of the zones of the forming-limit diagram.
#ifndef deepdraw_formability_formability_parameters_h
#define deepdraw_formability_formability_parameters_h

#include <deepdraw/formability/fld_zone.h>
#include <deepdraw/formability/forming_limit_curve.h>
#include <deepdraw/formability/marciniak_kuczynski.h>
#include <limits>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace deepdraw
{
  namespace formability
  {
    struct FormabilityParameters
    {
      enum class CurveType
      {
        none,
        tabulated,
        keeler_brazier,
        marciniak_kuczynski
      };

      CurveType curve_type = CurveType::none;

      // Tabulated: the points of Table or of Table file (only one of the
      // two; read and checked when the curve type is tabulated), and where
      // they came from, for messages ("Formability/Table" or the file).
      std::vector<FlcPoint> table;
      std::string           table_source;

      // Keeler-Brazier: n and t (mm); NaN = left empty, taken from
      // Material/Swift exponent and Geometry/Thickness (D133).
      double keeler_n         = std::numeric_limits<double>::quiet_NaN();
      double keeler_thickness = std::numeric_limits<double>::quiet_NaN();

      MarciniakKuczynskiParameters marciniak_kuczynski;

      FldZoneParameters zones;

      // Declares the entries inside the *current* subsection (the caller
      // enters "Formability"), with the subsection Marciniak-Kuczynski.
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      // Reads the current subsection, then validate(). A relative Table
      // file is taken relative to input_directory (the prm file's).
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &input_directory = ".");

      // Throws InputError naming the parameter ("Formability/Safety band")
      // and the allowed values.
      void
      validate() const;
    };
  } // namespace formability
} // namespace deepdraw

#endif
