// A forming-limit curve given by points (eps2, eps1), as labs deliver it, or
// as the Marciniak-Kuczynski analysis computes it: linear between the
// points, exact at them, and constant beyond the first and the last point
// (doc/decisions.md D131: the conservative side for the usual shapes).
#ifndef deepdraw_formability_tabulated_flc_h
#define deepdraw_formability_tabulated_flc_h

#include <deepdraw/formability/forming_limit_curve.h>

namespace deepdraw
{
  namespace formability
  {
    class TabulatedFlc : public FormingLimitCurve
    {
    public:
      // Checks that there are at least two points, every value is finite,
      // eps1 > 0, and eps2 strictly increases (a function of eps2); throws
      // InputError naming source ("Formability/Table", a file, ...).
      TabulatedFlc(const std::vector<FlcPoint> &points,
                   const std::string           &source,
                   const std::string           &description);

      double
      limit_major_strain(double minor_strain) const override;

      std::vector<FlcPoint>
      points() const override;

      std::string
      description() const override;

      // From the first to the last point.
      std::pair<double, double>
      minor_strain_range() const override;

    private:
      std::vector<FlcPoint> nodes;
      std::string           text;
    };

    // Parses "eps2, eps1; eps2, eps1; ..." (the value of Formability/Table);
    // InputError naming entry for a pair that is not two numbers.
    std::vector<FlcPoint>
    parse_flc_table(const std::string &text, const std::string &entry);

    // Reads a table file: one point "eps2 eps1" per line, separated by
    // commas, semicolons or blanks; '#' starts a comment; a first line that
    // is not numbers is a header (a CSV file with "eps2,eps1"). InputError
    // "FILE:LINE: ..." for anything else.
    std::vector<FlcPoint>
    read_flc_table_file(const std::string &filename);
  } // namespace formability
} // namespace deepdraw

#endif
