// The Keeler-Brazier curve (doc/theory_formability.md §2.2, D132).
#include <cmath>
#include <deepdraw/formability/keeler_brazier_flc.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/value_check.h>

namespace deepdraw
{
  namespace formability
  {
    namespace
    {
      // Right side slope in engineering strains, up to e2 = 0.2 in the
      // data the correlation rests on.
      constexpr double right_slope = 0.6;
    } // namespace


    KeelerBrazierFlc::KeelerBrazierFlc(const double       n,
                                       const double       thickness,
                                       const std::string &n_source,
                                       const std::string &thickness_source)
        : n(n)
        , thickness(thickness)
    {
      const auto check = [](const bool         inside,
                            const std::string &what,
                            const std::string &range,
                            const std::string &entry)
      {
        if (!inside)
          throw InputError("Keeler-Brazier curve: " + what
                           + " is outside the range of the correlation, "
                           + range + "; give Formability/" + entry
                           + ", or use a tabulated or Marciniak-Kuczynski "
                             "curve");
      };
      check(n > 0. && n <= 0.21,
            "the hardening exponent n = " + io::number_text(n) + " (" + n_source
              + ")",
            "0 < n <= 0.21 (low-carbon steels)",
            "Keeler-Brazier n");
      check(thickness > 0. && thickness <= 3.,
            "the thickness t = " + io::number_text(thickness) + " mm ("
              + thickness_source + ")",
            "0 < t <= 3 mm",
            "Keeler-Brazier thickness");
      eps1_0 = std::log1p(flc0_percent(n, thickness) / 100.);
    }


    double
    KeelerBrazierFlc::flc0_percent(const double n, const double thickness)
    {
      return (23.3 + 14.13 * thickness) * n / 0.21;
    }


    double
    KeelerBrazierFlc::limit_major_strain(const double minor_strain) const
    {
      // Left: constant thickness strain, eps1 + eps2 = eps1_0.
      if (minor_strain <= 0.)
        return eps1_0 - minor_strain;
      // Right: e1 = e1_0 + 0.6 e2 with e = exp(eps) - 1.
      const double e1_0 = std::expm1(eps1_0);
      return std::log1p(e1_0 + right_slope * std::expm1(minor_strain));
    }


    std::vector<FlcPoint>
    KeelerBrazierFlc::points() const
    {
      // 20 intervals on each side, so that FLC0 (the kink) is a point.
      const double          left = -eps1_0, right = std::log1p(0.2);
      std::vector<FlcPoint> samples;
      for (int k = -20; k <= 20; ++k)
      {
        FlcPoint point;
        point.minor_strain = (k < 0 ? -left : right) * k / 20.;
        point.major_strain = limit_major_strain(point.minor_strain);
        samples.push_back(point);
      }
      return samples;
    }


    std::string
    KeelerBrazierFlc::description() const
    {
      return "Keeler-Brazier, n = " + io::number_text(n)
             + ", t = " + io::number_text(thickness) + " mm";
    }
  } // namespace formability
} // namespace deepdraw
