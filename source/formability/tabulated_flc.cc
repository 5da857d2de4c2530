// Tabulated forming-limit curves: checks, interpolation, the prm table and
// table files (doc/theory_formability.md §2.1, D131).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <deepdraw/formability/tabulated_flc.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/text_file.h>
#include <deepdraw/io/value_check.h>
#include <sstream>

namespace deepdraw
{
  namespace formability
  {
    namespace
    {
      // The whole token must be a number; "nan" and "inf" are numbers here,
      // so that the check of the curve names them as non-finite values.
      bool
      to_number(const std::string &token, double &value)
      {
        if (token.empty())
          return false;
        char *end = nullptr;
        value     = std::strtod(token.c_str(), &end);
        return end == token.c_str() + token.size();
      }

      // Splits at commas, semicolons and whitespace.
      std::vector<std::string>
      tokens_of(std::string text)
      {
        std::replace_if(
          text.begin(),
          text.end(),
          [](const char c) { return c == ',' || c == ';'; },
          ' ');
        std::istringstream       in(text);
        std::vector<std::string> tokens;
        for (std::string token; in >> token;)
          tokens.push_back(token);
        return tokens;
      }

      // Two numbers "eps2 eps1"; false for anything else.
      bool
      to_point(const std::string &text, FlcPoint &point)
      {
        const std::vector<std::string> tokens = tokens_of(text);
        return tokens.size() == 2 && to_number(tokens[0], point.minor_strain)
               && to_number(tokens[1], point.major_strain);
      }

      std::string
      describe(const std::vector<FlcPoint> &points, const std::size_t k)
      {
        return "point " + std::to_string(k + 1)
               + " (eps2 = " + io::number_text(points[k].minor_strain)
               + ", eps1 = " + io::number_text(points[k].major_strain) + ")";
      }
    } // namespace


    TabulatedFlc::TabulatedFlc(const std::vector<FlcPoint> &points,
                               const std::string           &source,
                               const std::string           &description)
        : nodes(points)
        , text(description)
    {
      const auto fail = [&](const std::string &what)
      { throw InputError(source + ": " + what); };
      if (points.empty())
        fail("the forming-limit table is empty; it needs at least 2 points "
             "(eps2, eps1)");
      if (points.size() < 2)
        fail("a forming-limit curve needs at least 2 points (eps2, eps1), "
             "got 1");
      for (std::size_t k = 0; k < points.size(); ++k)
      {
        if (!std::isfinite(points[k].minor_strain)
            || !std::isfinite(points[k].major_strain))
          fail(describe(points, k)
               + " is not finite: allowed values are finite numbers");
        if (!(points[k].major_strain > 0.))
          fail(describe(points, k)
               + ": allowed values of the major strain are eps1 > 0");
        if (k > 0 && !(points[k].minor_strain > points[k - 1].minor_strain))
          fail(describe(points, k) + " does not follow "
               + describe(points, k - 1)
               + ": eps2 must increase strictly from point to point (the "
                 "curve must be a function of eps2)");
      }
    }


    double
    TabulatedFlc::limit_major_strain(const double minor_strain) const
    {
      if (!(minor_strain > nodes.front().minor_strain))
        return nodes.front().major_strain;
      if (!(minor_strain < nodes.back().minor_strain))
        return nodes.back().major_strain;
      // The first node above minor_strain; nodes[k-1] <= minor < nodes[k].
      const auto above
        = std::upper_bound(nodes.begin(),
                           nodes.end(),
                           minor_strain,
                           [](const double value, const FlcPoint &node)
                           { return value < node.minor_strain; });
      const FlcPoint &a = *(above - 1), &b = *above;
      const double    w
        = (minor_strain - a.minor_strain) / (b.minor_strain - a.minor_strain);
      return (1. - w) * a.major_strain + w * b.major_strain;
    }


    std::vector<FlcPoint>
    TabulatedFlc::points() const
    {
      return nodes;
    }


    std::string
    TabulatedFlc::description() const
    {
      return text;
    }


    std::pair<double, double>
    TabulatedFlc::minor_strain_range() const
    {
      return {nodes.front().minor_strain, nodes.back().minor_strain};
    }


    std::vector<FlcPoint>
    parse_flc_table(const std::string &text, const std::string &entry)
    {
      std::vector<FlcPoint> points;
      std::istringstream    pairs(text);
      for (std::string pair; std::getline(pairs, pair, ';');)
      {
        if (pair.find_first_not_of(" \t") == std::string::npos)
          continue;
        FlcPoint point;
        if (!to_point(pair, point))
          throw InputError(entry
                           + ": expected pairs 'eps2, eps1' separated "
                             "by semicolons, got '"
                           + io::one_line(pair, 200) + "'");
        points.push_back(point);
      }
      return points;
    }


    std::vector<FlcPoint>
    read_flc_table_file(const std::string &filename)
    {
      std::istringstream in(
        io::read_text_file(filename, "forming-limit table file"));
      std::vector<FlcPoint> points;
      bool                  header_allowed = true;
      std::string           line;
      for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        line = line.substr(0, line.find('#'));
        if (tokens_of(line).empty())
          continue;
        // A first line without any number is a header ("eps2,eps1").
        const std::vector<std::string> tokens = tokens_of(line);
        double                         value  = 0.;
        const bool                     header = header_allowed
                            && std::none_of(tokens.begin(),
                                            tokens.end(),
                                            [&](const std::string &token) {
                                              return to_number(token, value);
                                            });
        header_allowed = false;
        FlcPoint point;
        if (to_point(line, point))
          points.push_back(point);
        else if (!header)
          throw InputError(io::one_line(filename, 300) + ":"
                           + std::to_string(number)
                           + ": expected two numbers 'eps2, eps1', got '"
                           + io::one_line(line, 200) + "'");
      }
      return points;
    }
  } // namespace formability
} // namespace deepdraw
