// Subsection Formability (doc/user_guide.md §8).
#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deepdraw/formability/formability_parameters.h>
#include <deepdraw/formability/number_entries.h>
#include <deepdraw/formability/tabulated_flc.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/value_check.h>
#include <filesystem>

namespace deepdraw
{
  namespace formability
  {
    namespace
    {
      using dealii::Patterns::Double;

      void
      require(const bool         condition,
              const std::string &entry,
              const double       value,
              const std::string &allowed)
      {
        io::require_value(condition, "Formability/" + entry, value, allowed);
      }

      // An entry that may be left empty: NaN then.
      double
      optional_number(const std::string &text,
                      const std::string &entry,
                      const std::string &when_empty)
      {
        const std::string value = dealii::Utilities::trim(text);
        if (value.empty())
          return std::numeric_limits<double>::quiet_NaN();
        if (!Double(-Double::max_double_value, Double::max_double_value)
               .match(value))
          throw InputError("Invalid value '" + io::one_line(value, 200)
                           + "' of Formability/" + entry
                           + ": allowed values are a number, or empty for "
                           + when_empty + ".");
        return dealii::Utilities::string_to_double(value);
      }

      // The points of the Table entry or of the Table file (relative to
      // input_directory), and their source for messages.
      void
      read_table(const std::string     &inline_table,
                 const std::string     &file,
                 const std::string     &input_directory,
                 std::vector<FlcPoint> &table,
                 std::string           &source)
      {
        if (!inline_table.empty() && !file.empty())
          throw InputError("Formability/Table and Formability/Table file are "
                           "both given: give the tabulated curve in only one "
                           "of them");
        if (inline_table.empty() && file.empty())
          throw InputError("Formability/Forming limit curve = tabulated needs "
                           "Formability/Table or Formability/Table file; both "
                           "are empty (the table is empty)");
        if (!inline_table.empty())
        {
          source = "Formability/Table";
          table  = parse_flc_table(inline_table, source);
          return;
        }
        source = std::filesystem::path(file).is_absolute()
                   ? file
                   : (std::filesystem::path(input_directory) / file).string();
        table  = read_flc_table_file(source);
      }


    } // namespace


    void
    FormabilityParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry(
        "Forming limit curve",
        "none",
        dealii::Patterns::Selection(
          "none|tabulated|Keeler-Brazier|Marciniak-Kuczynski"),
        "The forming-limit curve (FLC): none; tabulated (Table or Table "
        "file); Keeler-Brazier (low-carbon steels, from n and t); "
        "Marciniak-Kuczynski (computed from subsection Material).");
      prm.declare_entry("Table",
                        "",
                        dealii::Patterns::Anything(),
                        "Tabulated FLC as pairs of true strains 'eps2, eps1; "
                        "eps2, eps1; ...', eps2 strictly increasing, eps1 > "
                        "0; linear between the points, constant beyond.");
      prm.declare_entry("Table file",
                        "",
                        dealii::Patterns::Anything(),
                        "Tabulated FLC from a file (relative to the prm "
                        "file): a point 'eps2, eps1' per line, '#' comments, "
                        "an optional header line. Not together with Table.");
      prm.declare_entry("Keeler-Brazier n",
                        "",
                        dealii::Patterns::Anything(),
                        "Hardening exponent n of the Keeler-Brazier curve, 0 "
                        "< n <= 0.21; empty: Material/Swift exponent.");
      prm.declare_entry("Keeler-Brazier thickness",
                        "",
                        dealii::Patterns::Anything(),
                        "Sheet thickness of the Keeler-Brazier curve, mm, 0 "
                        "< t <= 3; empty: Geometry/Thickness.");
      FldZoneParameters zones;
      declare_number_entries(prm, number_entries(zones));
      MarciniakKuczynskiParameters marciniak_kuczynski;
      prm.enter_subsection("Marciniak-Kuczynski");
      declare_number_entries(prm, number_entries(marciniak_kuczynski));
      prm.leave_subsection();
    }


    void
    FormabilityParameters::parse_parameters(dealii::ParameterHandler &prm,
                                            const std::string &input_directory)
    {
      const std::string curve = prm.get("Forming limit curve");
      if (curve == "tabulated")
        curve_type = CurveType::tabulated;
      else if (curve == "Keeler-Brazier")
        curve_type = CurveType::keeler_brazier;
      else if (curve == "Marciniak-Kuczynski")
        curve_type = CurveType::marciniak_kuczynski;
      else
        curve_type = CurveType::none;
      keeler_n         = optional_number(prm.get("Keeler-Brazier n"),
                                 "Keeler-Brazier n",
                                 "Material/Swift exponent");
      keeler_thickness = optional_number(prm.get("Keeler-Brazier thickness"),
                                         "Keeler-Brazier thickness",
                                         "Geometry/Thickness");
      parse_number_entries(prm, number_entries(zones));
      prm.enter_subsection("Marciniak-Kuczynski");
      parse_number_entries(prm, number_entries(marciniak_kuczynski));
      prm.leave_subsection();
      if (curve_type == CurveType::tabulated)
        read_table(dealii::Utilities::trim(prm.get("Table")),
                   dealii::Utilities::trim(prm.get("Table file")),
                   input_directory,
                   table,
                   table_source);
      validate();
    }


    void
    FormabilityParameters::validate() const
    {
      marciniak_kuczynski.validate();
      FldZoneParameters copy = zones;
      validate_number_entries(number_entries(copy), "Formability/");
      if (!std::isnan(keeler_n))
        require(std::isfinite(keeler_n),
                "Keeler-Brazier n",
                keeler_n,
                "a finite number, or empty");
      if (!std::isnan(keeler_thickness))
        require(std::isfinite(keeler_thickness),
                "Keeler-Brazier thickness",
                keeler_thickness,
                "a finite number, or empty");
      if (curve_type == CurveType::tabulated)
        TabulatedFlc(table, table_source, "");
    }
  } // namespace formability
} // namespace deepdraw
