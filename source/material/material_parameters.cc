#include <algorithm>
#include <cmath>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/material/material_parameters.h>
#include <deepdraw/material/yld2004_criterion.h>
#include <sstream>
#include <string>

namespace deepdraw
{
  namespace material
  {
    namespace
    {
      // Defaults in the prm come from the struct initialisers, so the two
      // cannot diverge.
      std::string
      to_string(const double value)
      {
        std::ostringstream s;
        s.precision(12);
        s << value;
        return s.str();
      }

      std::string
      name(const std::string &entry)
      {
        return "Material/" + entry;
      }

      void
      require(const bool         condition,
              const std::string &entry,
              const double       value,
              const std::string &allowed)
      {
        if (!condition)
          throw InputError("Invalid value " + to_string(value) + " of "
                           + name(entry) + ": allowed values are " + allowed
                           + ".");
      }

      // Entry names of the Yld2004-18p coefficients, in the paper's order
      // (MaterialParameters::yld2004_c1): "Yld2004 c'12", "Yld2004 c''12".
      const char *const yld2004_indices[9]
        = {"12", "13", "21", "23", "31", "32", "44", "55", "66"};

      std::string
      yld2004_entry(const unsigned int transformation, const unsigned int k)
      {
        return std::string("Yld2004 c") + (transformation == 0 ? "'" : "''")
               + yld2004_indices[k];
      }

      std::string
      table_to_string(const std::vector<std::pair<double, double>> &table)
      {
        std::string text;
        for (const auto &[strain, stress] : table)
          text += (text.empty() ? "" : ", ") + to_string(strain) + ":"
                  + to_string(stress);
        return text;
      }

      // "e1:Y1, e2:Y2, ..." -> pairs; the values are checked by validate().
      std::vector<std::pair<double, double>>
      parse_table(const std::string &text)
      {
        const std::string allowed
          = "comma-separated pairs plastic strain:yield stress, e.g. "
            "\"0:150, 0.1:230, 0.5:300\"";
        std::vector<std::pair<double, double>> table;
        std::istringstream                     entries(text);
        std::string                            entry;
        while (std::getline(entries, entry, ','))
        {
          const auto first = entry.find_first_not_of(" \t");
          entry            = first == std::string::npos
                               ? ""
                               : entry.substr(first,
                                   entry.find_last_not_of(" \t") - first + 1);
          std::istringstream pair(entry);
          double             strain, stress;
          char               colon = 0;
          std::string        rest;
          if (!(pair >> strain >> colon >> stress) || colon != ':'
              || (pair >> rest))
            throw InputError("Invalid entry \"" + entry + "\" of "
                             + name("Hardening table") + ": allowed values are "
                             + allowed + ".");
          table.emplace_back(strain, stress);
        }
        if (table.empty())
          throw InputError("Empty " + name("Hardening table")
                           + ": allowed values are " + allowed + ".");
        return table;
      }


      void
      declare_yld2004_parameters(dealii::ParameterHandler &prm)
      {
        const MaterialParameters d;
        prm.declare_entry(
          "Yield criterion",
          "Hill48",
          dealii::Patterns::Selection("Hill48|Yld2004-18p"),
          "Hill48 (Hill F ... Hill N) or Yld2004-18p (Barlat et al. 2005: "
          "Yld2004 c'12 ... c''66 and Yld2004 exponent), in the material "
          "axes 1 = rolling, 2 = transverse, 3 = normal. Both are scaled so "
          "that the equivalent stress of uniaxial tension in the rolling "
          "direction is that stress, i.e. the hardening law is the "
          "rolling-direction curve.");
        for (unsigned int t = 0; t < 2; ++t)
          for (unsigned int k = 0; k < 9; ++k)
            prm.declare_entry(
              yld2004_entry(t, k),
              to_string((t == 0 ? d.yld2004_c1 : d.yld2004_c2)[k]),
              dealii::Patterns::Double(),
              std::string("Yld2004-18p coefficient of the ")
                + (t == 0 ? "first" : "second")
                + " linear transformation (C' or C''), dimensionless "
                  "(-100 to 100; indices 4 = 23 (yz), 5 = 31 (zx), 6 = 12 "
                  "(xy) as in Barlat et al. 2005). All 1: isotropic.");
        prm.declare_entry("Yld2004 exponent",
                          to_string(d.yld2004_exponent),
                          dealii::Patterns::Double(),
                          "Exponent a of Yld2004-18p, dimensionless (2 <= a <= "
                          "50; 6 for bcc, 8 for fcc metals such as "
                          "aluminium).");
      }


      void
      validate_yld2004(const MaterialParameters &p)
      {
        for (unsigned int t = 0; t < 2; ++t)
          for (unsigned int k = 0; k < 9; ++k)
          {
            const double c = (t == 0 ? p.yld2004_c1 : p.yld2004_c2)[k];
            require(c >= -100. && c <= 100.,
                    yld2004_entry(t, k),
                    c,
                    "-100 to 100");
          }
        // Below 2 the criterion is convex but not twice differentiable
        // where eigenvalues of C's and C''s coincide: no exact tangent.
        require(p.yld2004_exponent >= 2. && p.yld2004_exponent <= 50.,
                "Yld2004 exponent",
                p.yld2004_exponent,
                "2 <= a <= 50");
        // A shear stress neither transformation sees.
        const char *const plane[3] = {"23 (yz)", "31 (zx)", "12 (xy)"};
        for (unsigned int k = 6; k < 9; ++k)
          if (std::max(std::abs(p.yld2004_c1[k]), std::abs(p.yld2004_c2[k]))
              <= 1e-6)
            throw InputError(
              "Invalid values " + to_string(p.yld2004_c1[k]) + " of "
              + name(yld2004_entry(0, k)) + " and " + to_string(p.yld2004_c2[k])
              + " of " + name(yld2004_entry(1, k))
              + ": allowed values are pairs with one of them non-zero (|c| > "
                "1e-6); otherwise the shear stress "
              + plane[k - 6] + " has zero equivalent stress.");
        // Convex for every coefficient set (doc/theory_material.md §1.2);
        // what can go wrong is a deviator with zero equivalent stress.
        const std::string degenerate
          = Yld2004Criterion::degenerate_mode(p.yld2004_c1, p.yld2004_c2);
        if (!degenerate.empty())
          throw InputError(
            "Invalid coefficients " + name("Yld2004 c'12") + " ... "
            + name("Yld2004 c''66") + ": " + degenerate
            + " has zero equivalent stress (an unbounded yield surface); "
              "allowed values are sets for which every non-zero stress "
              "deviator has a positive equivalent stress.");
      }


      void
      validate_hardening(const MaterialParameters &p)
      {
        require(p.voce_A > 0. && p.voce_A <= 1e15,
                "Voce A",
                p.voce_A,
                "0 < A <= 1e15 (MPa)");
        require(p.voce_B >= 0. && p.voce_B < p.voce_A,
                "Voce B",
                p.voce_B,
                "0 <= B < Voce A = " + to_string(p.voce_A)
                  + " (MPa; the initial yield stress A - B must be "
                    "positive, and B >= 0 keeps the law hardening)");
        require(p.voce_C >= 0. && p.voce_C <= 1e6,
                "Voce C",
                p.voce_C,
                "0 <= C <= 1e6");
        const auto &table = p.hardening_table;
        require(!table.empty() && table.size() <= 10000,
                "Hardening table",
                table.size(),
                "1 to 10000 pairs");
        require(table[0].first == 0.,
                "Hardening table",
                table[0].first,
                "a first plastic strain of 0");
        for (unsigned int k = 0; k < table.size(); ++k)
        {
          const auto [strain, stress] = table[k];
          require(stress > 0. && stress <= 1e15,
                  "Hardening table",
                  stress,
                  "yield stresses 0 < Y <= 1e15 (MPa)");
          if (k == 0)
            continue;
          require(strain > table[k - 1].first && strain <= 100.,
                  "Hardening table",
                  strain,
                  "strictly increasing plastic strains up to 100 (after "
                    + to_string(table[k - 1].first) + ")");
          require(stress >= table[k - 1].second,
                  "Hardening table",
                  stress,
                  "non-decreasing yield stresses (after "
                    + to_string(table[k - 1].second)
                    + " MPa; softening is not supported)");
        }
      }
    } // namespace


    void
    MaterialParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Double;
      const MaterialParameters d;
      const double             inf = Double::max_double_value;

      prm.declare_entry(
        "Young's modulus",
        to_string(d.youngs_modulus),
        Double(0., inf),
        "Young's modulus E of the sheet, in MPa (0 < E <= 1e7).");
      prm.declare_entry("Poisson's ratio",
                        to_string(d.poissons_ratio),
                        Double(-1., 0.5),
                        "Poisson's ratio nu, dimensionless (-1 < nu < 0.5).");
      const char  *normal[3]         = {"F", "G", "H"};
      const double normal_default[3] = {d.hill_F, d.hill_G, d.hill_H};
      for (unsigned int i = 0; i < 3; ++i)
        prm.declare_entry(std::string("Hill ") + normal[i],
                          to_string(normal_default[i]),
                          Double(0., inf),
                          std::string("Hill'48 coefficient ") + normal[i]
                            + ", dimensionless (0 to 100; F + G, G + H, F + "
                              "H > 0). Axes: 1 = rolling, 2 = transverse, 3 = "
                              "normal. Von Mises: F = G = H = 0.5.");
      const char  *shear[3]         = {"L", "M", "N"};
      const char  *plane[3]         = {"23", "31", "12"};
      const double shear_default[3] = {d.hill_L, d.hill_M, d.hill_N};
      for (unsigned int i = 0; i < 3; ++i)
        prm.declare_entry(std::string("Hill ") + shear[i],
                          to_string(shear_default[i]),
                          Double(0., inf),
                          std::string("Hill'48 shear coefficient ") + shear[i]
                            + " (plane " + plane[i]
                            + "), dimensionless (0 < value <= 100). Von "
                              "Mises: 1.5.");
      declare_yld2004_parameters(prm);
      prm.declare_entry("Hardening law",
                        "Swift",
                        dealii::Patterns::Selection("Swift|Voce|tabulated"),
                        "Isotropic hardening Y(epbar), the yield stress of "
                        "uniaxial tension in the rolling direction: Swift "
                        "(Swift coefficient/prestrain/exponent), Voce (Voce "
                        "A/B/C) or tabulated (Hardening table).");
      prm.declare_entry("Swift coefficient",
                        to_string(d.swift_coefficient),
                        Double(0., inf),
                        "C of the Swift law Y = C (eps0 + epbar)^n, in MPa "
                        "(0 < C <= 1e15; a very large C keeps the sheet "
                        "elastic).");
      prm.declare_entry("Swift prestrain",
                        to_string(d.swift_prestrain),
                        Double(0., inf),
                        "eps0 of the Swift law, dimensionless (0 < eps0 <= "
                        "10, so that the initial yield stress C eps0^n is "
                        "positive).");
      prm.declare_entry("Swift exponent",
                        to_string(d.swift_exponent),
                        Double(0., 1.),
                        "n of the Swift law, dimensionless (0 <= n < 1; 0 = "
                        "perfectly plastic).");
      prm.declare_entry("Voce A",
                        to_string(d.voce_A),
                        Double(),
                        "A of the Voce law Y = A - B exp(-C epbar), the "
                        "saturation stress, in MPa (0 < A <= 1e15).");
      prm.declare_entry("Voce B",
                        to_string(d.voce_B),
                        Double(),
                        "B of the Voce law, in MPa (0 <= B < A: the initial "
                        "yield stress A - B is positive).");
      prm.declare_entry("Voce C",
                        to_string(d.voce_C),
                        Double(),
                        "C of the Voce law, dimensionless (0 <= C <= 1e6).");
      prm.declare_entry(
        "Hardening table",
        table_to_string(d.hardening_table),
        dealii::Patterns::Anything(),
        "Tabulated Y(epbar): comma-separated pairs epbar:Y (Y in MPa), "
        "piecewise linear, the last segment's slope continued beyond the last "
        "point. The first strain is 0, the strains increase strictly, the "
        "stresses are positive and do not decrease (at most 10000 pairs).");
      prm.declare_entry("Prager modulus",
                        to_string(d.prager_modulus),
                        Double(0., inf),
                        "k of the Prager kinematic hardening dX = k "
                        "d(eps^p), in MPa (0 to 1e7; 0 switches it off).");
      prm.declare_entry("Rolling direction angle",
                        to_string(d.rolling_direction_angle),
                        Double(-180., 180.),
                        "Angle from the global x axis (the blank's length) "
                        "to the rolling direction (Hill axis 1), "
                        "counterclockwise about the sheet normal z, in "
                        "degrees (-180 to 180): the initial material axes "
                        "are this rotation about z. 0: rolling direction = "
                        "x; 90: rolling direction = y.");
    }


    void
    MaterialParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      youngs_modulus  = prm.get_double("Young's modulus");
      poissons_ratio  = prm.get_double("Poisson's ratio");
      hill_F          = prm.get_double("Hill F");
      hill_G          = prm.get_double("Hill G");
      hill_H          = prm.get_double("Hill H");
      hill_L          = prm.get_double("Hill L");
      hill_M          = prm.get_double("Hill M");
      hill_N          = prm.get_double("Hill N");
      yield_criterion = prm.get("Yield criterion") == "Hill48"
                          ? YieldCriterion::hill48
                          : YieldCriterion::yld2004_18p;
      for (unsigned int k = 0; k < 9; ++k)
      {
        yld2004_c1[k] = prm.get_double(yld2004_entry(0, k));
        yld2004_c2[k] = prm.get_double(yld2004_entry(1, k));
      }
      yld2004_exponent        = prm.get_double("Yld2004 exponent");
      swift_coefficient       = prm.get_double("Swift coefficient");
      swift_prestrain         = prm.get_double("Swift prestrain");
      swift_exponent          = prm.get_double("Swift exponent");
      const std::string law   = prm.get("Hardening law");
      hardening_law           = law == "Swift"  ? HardeningLawType::swift
                                : law == "Voce" ? HardeningLawType::voce
                                                : HardeningLawType::tabulated;
      voce_A                  = prm.get_double("Voce A");
      voce_B                  = prm.get_double("Voce B");
      voce_C                  = prm.get_double("Voce C");
      hardening_table         = parse_table(prm.get("Hardening table"));
      prager_modulus          = prm.get_double("Prager modulus");
      rolling_direction_angle = prm.get_double("Rolling direction angle");
      validate();
    }


    void
    MaterialParameters::validate() const
    {
      // Written as !(a < b) etc. where needed so that NaN is rejected too.
      // Upper bounds (D50) far above any metal, so that no product of
      // them overflows in the stress update.
      require(youngs_modulus > 0. && youngs_modulus <= 1e7,
              "Young's modulus",
              youngs_modulus,
              "0 < E <= 1e7 (MPa)");
      require(poissons_ratio > -1. && poissons_ratio < 0.5,
              "Poisson's ratio",
              poissons_ratio,
              "-1 < nu < 0.5 (0.5 is incompressible, not supported)");
      require(hill_F >= 0. && hill_F <= 100., "Hill F", hill_F, "0 to 100");
      require(hill_G >= 0. && hill_G <= 100., "Hill G", hill_G, "0 to 100");
      require(hill_H >= 0. && hill_H <= 100., "Hill H", hill_H, "0 to 100");
      // Pairwise sums > 0 make M positive definite on deviators, so the
      // yield surface is bounded (doc/theory_material.md).
      require(hill_G + hill_H > 0.,
              "Hill G",
              hill_G,
              "such that Material/Hill G + Material/Hill H > 0 (Hill H = "
                + to_string(hill_H) + ")");
      require(hill_F + hill_H > 0.,
              "Hill F",
              hill_F,
              "such that Material/Hill F + Material/Hill H > 0 (Hill H = "
                + to_string(hill_H) + ")");
      require(hill_F + hill_G > 0.,
              "Hill F",
              hill_F,
              "such that Material/Hill F + Material/Hill G > 0 (Hill G = "
                + to_string(hill_G) + ")");
      require(hill_L > 0. && hill_L <= 100., "Hill L", hill_L, "0 < L <= 100");
      require(hill_M > 0. && hill_M <= 100., "Hill M", hill_M, "0 < M <= 100");
      require(hill_N > 0. && hill_N <= 100., "Hill N", hill_N, "0 < N <= 100");
      // Tests keep a sheet elastic with C = 1e12.
      require(swift_coefficient > 0. && swift_coefficient <= 1e15,
              "Swift coefficient",
              swift_coefficient,
              "0 < C <= 1e15 (MPa)");
      require(swift_prestrain > 0. && swift_prestrain <= 10.,
              "Swift prestrain",
              swift_prestrain,
              "0 < eps0 <= 10 (the initial yield stress C eps0^n must be "
              "finite and positive)");
      require(swift_exponent >= 0. && swift_exponent < 1.,
              "Swift exponent",
              swift_exponent,
              "0 <= n < 1");
      validate_yld2004(*this);
      validate_hardening(*this);
      require(prager_modulus >= 0. && prager_modulus <= 1e7,
              "Prager modulus",
              prager_modulus,
              "0 <= k <= 1e7 (MPa)");
      require(rolling_direction_angle >= -180.
                && rolling_direction_angle <= 180.,
              "Rolling direction angle",
              rolling_direction_angle,
              "-180 to 180 (degrees)");
    }


    dealii::Tensor<2, 3>
    MaterialParameters::initial_material_axes() const
    {
      const double angle = rolling_direction_angle * dealii::numbers::PI / 180.;
      double       c = std::cos(angle), s = std::sin(angle);
      // cos(90 degrees) is 6e-17, not 0: quarter turns are made exact, so
      // that the default 0 gives R0 = I and 90 the exact swap of x and y.
      if (std::abs(c) < 1e-15)
        c = 0.;
      if (std::abs(s) < 1e-15)
        s = 0.;
      dealii::Tensor<2, 3> R;
      R[0][0] = c;
      R[1][0] = s;
      R[0][1] = -s;
      R[1][1] = c;
      R[2][2] = 1.;
      return R;
    }
  } // namespace material
} // namespace deepdraw
