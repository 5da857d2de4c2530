// MaterialParameters: declared entries and their defaults, parsing inside
// "subsection Material", and the checks a Pattern cannot make: a bad value
// throws deepdraw::InputError whose message names "Material/<entry>".
#include "../test_utilities.h"

#include <deal.II/base/parameter_handler.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/material/elasto_plasticity.h>
#include <deepdraw/material/material_parameters.h>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using deepdraw::material::MaterialParameters;

namespace
{
  // Parses "subsection Material" with the given body; returns the InputError
  // message, or "" if parsing succeeded.
  std::string
  parse(const std::string &body, MaterialParameters &parameters)
  {
    dealii::ParameterHandler prm;
    prm.enter_subsection("Material");
    MaterialParameters::declare_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string("subsection Material\n" + body + "\nend\n");
    prm.enter_subsection("Material");
    try
    {
      parameters.parse_parameters(prm);
    }
    catch (const deepdraw::InputError &e)
    {
      prm.leave_subsection();
      return e.what();
    }
    prm.leave_subsection();
    return "";
  }

  // C' and C'' without their normal coefficients: S', S'' have no normal
  // part, so every normal deviator has sigma_bar = 0.
  std::string
  zero_normal_coefficients()
  {
    std::string body;
    for (const char *prime : {"'", "''"})
      for (const char *index : {"12", "13", "21", "23", "31", "32"})
        body += std::string("set Yld2004 c") + prime + index + " = 0\n";
    return body;
  }

  // c12 = -c21 = c32 - c31 = 1 in both transformations: C' s = C'' s =
  // (1, 1, 1) for s = (1, -1, 0), so phi(s) = 0 although no coefficient of
  // S_xx, S_yy is zero.
  std::string
  degenerate_normal_coefficients()
  {
    std::string body;
    for (const char *prime : {"'", "''"})
      body += std::string("set Yld2004 c") + prime + "12 = 1\n"
              + "set Yld2004 c" + prime + "21 = -1\n" + "set Yld2004 c" + prime
              + "31 = 0\n" + "set Yld2004 c" + prime + "32 = 1\n";
    return body;
  }
} // namespace

int
main()
{
  // Defaults = the struct initialisers (NUMISHEET'93).
  {
    MaterialParameters parameters;
    parameters.hill_F = -1.; // overwritten by parsing
    deepdraw_test::check_true("defaults parse", parse("", parameters).empty());
    const MaterialParameters d;
    deepdraw_test::check_close("Hill F default",
                               parameters.hill_F,
                               d.hill_F,
                               0.);
    deepdraw_test::check_close("Swift coefficient default",
                               parameters.swift_coefficient,
                               576.79,
                               0.);
    deepdraw_test::check_close("Swift exponent default",
                               parameters.swift_exponent,
                               0.3593,
                               0.);
    deepdraw_test::check_true("Swift is the default hardening law",
                              parameters.hardening_law
                                == deepdraw::material::HardeningLawType::swift);
    deepdraw_test::check_true("default table parsed back",
                              parameters.hardening_table == d.hardening_table);
    deepdraw_test::check_true("Hill48 is the default criterion",
                              parameters.yield_criterion
                                == deepdraw::material::YieldCriterion::hill48);
    deepdraw_test::check_true("Yld2004 coefficients default to 1, a = 8",
                              parameters.yld2004_c1 == d.yld2004_c1
                                && parameters.yld2004_c2 == d.yld2004_c2
                                && d.yld2004_c2[4] == 1.
                                && parameters.yld2004_exponent == 8.);
  }
  // All entries are read.
  {
    MaterialParameters parameters;
    const std::string  body
      = "set Young's modulus = 210000\nset Poisson's ratio = 0.3\n"
        "set Hill F = 0.1\nset Hill G = 0.2\nset Hill H = 0.3\n"
        "set Hill L = 1.1\nset Hill M = 1.2\nset Hill N = 1.3\n"
        "set Swift coefficient = 500\nset Swift prestrain = 0.02\n"
        "set Swift exponent = 0.25\nset Prager modulus = 1000\n"
        "set Rolling direction angle = 30\nset Hardening law = Voce\n"
        "set Voce A = 300\nset Voce B = 120\nset Voce C = 9.5\n"
        "set Hardening table = 0:120, 0.05 : 180,0.4:260\n"
        "set Yield criterion = Yld2004-18p\nset Yld2004 exponent = 6\n"
        "set Yld2004 c'13 = 0.9\nset Yld2004 c''66 = 1.4\n"
        "set Yld2004 c'44 = 1.05";
    deepdraw_test::check_true("custom values parse",
                              parse(body, parameters).empty());
    deepdraw_test::check_true("Hardening law = Voce read",
                              parameters.hardening_law
                                == deepdraw::material::HardeningLawType::voce);
    deepdraw_test::check_true("three table pairs read",
                              parameters.hardening_table.size() == 3);
    deepdraw_test::check_true(
      "Yield criterion = Yld2004-18p read",
      parameters.yield_criterion
        == deepdraw::material::YieldCriterion::yld2004_18p);
    const double read[] = {parameters.youngs_modulus,
                           parameters.poissons_ratio,
                           parameters.hill_F,
                           parameters.hill_G,
                           parameters.hill_H,
                           parameters.hill_L,
                           parameters.hill_M,
                           parameters.hill_N,
                           parameters.swift_coefficient,
                           parameters.swift_prestrain,
                           parameters.swift_exponent,
                           parameters.prager_modulus,
                           parameters.rolling_direction_angle,
                           parameters.voce_A,
                           parameters.voce_B,
                           parameters.voce_C,
                           parameters.hardening_table[1].first,
                           parameters.hardening_table[1].second,
                           parameters.hardening_table[2].second,
                           parameters.yld2004_exponent,
                           parameters.yld2004_c1[1],
                           parameters.yld2004_c2[8],
                           parameters.yld2004_c1[6],
                           parameters.yld2004_c1[0]};
    const double expected[]
      = {210000, 0.3, 0.1, 0.2, 0.3,  1.1, 1.2, 1.3, 500, 0.02, 0.25, 1000,
         30,     300, 120, 9.5, 0.05, 180, 260, 6,   0.9, 1.4,  1.05, 1};
    for (unsigned int i = 0; i < std::size(expected); ++i)
      deepdraw_test::check_close("entry " + std::to_string(i),
                                 read[i],
                                 expected[i],
                                 0.);
  }

  // Values a Pattern lets through but the model cannot use.
  const std::vector<std::pair<std::string, std::string>> bad
    = {{"set Young's modulus = 0", "Material/Young's modulus"},
       {"set Poisson's ratio = 0.5", "Material/Poisson's ratio"},
       {"set Swift coefficient = 0", "Material/Swift coefficient"},
       {"set Swift prestrain = 0", "Material/Swift prestrain"},
       {"set Swift exponent = 1", "Material/Swift exponent"},
       {"set Hill G = 0\nset Hill H = 0", "Material/Hill G"},
       {"set Hill F = 0\nset Hill H = 0", "Material/Hill F"},
       {"set Hill F = 0\nset Hill G = 0", "Material/Hill F"},
       {"set Hill L = 0", "Material/Hill L"},
       {"set Hill M = 0", "Material/Hill M"},
       {"set Hill N = 0", "Material/Hill N"},
       {"set Voce A = 0", "Material/Voce A"},
       {"set Voce B = 500", "Material/Voce B"}, // >= A: Y(0) <= 0
       {"set Voce B = -1", "Material/Voce B"},  // softening
       {"set Voce C = -2", "Material/Voce C"},
       {"set Hardening table = 0:100, 0.1", "Material/Hardening table"},
       {"set Hardening table = 0:100, 0.1:abc", "Material/Hardening table"},
       {"set Hardening table = 0.01:100, 0.1:120", "Material/Hardening table"},
       {"set Hardening table = 0:100, 0.1:120, 0.1:130",
        "Material/Hardening table"},
       {"set Hardening table = 0:100, 0.2:120, 0.1:130",
        "Material/Hardening table"},
       {"set Hardening table = 0:100, 0.1:90", "Material/Hardening table"},
       {"set Hardening table = 0:-5", "Material/Hardening table"},
       {"set Hardening table = 0:100, 0.1:inf", "Material/Hardening table"},
       {"set Hardening table = ", "Material/Hardening table"},
       {"set Yld2004 exponent = 1.5", "Material/Yld2004 exponent"},
       {"set Yld2004 exponent = 60", "Material/Yld2004 exponent"},
       {"set Yld2004 c'12 = 150", "Material/Yld2004 c'12"},
       {"set Yld2004 c''55 = -101", "Material/Yld2004 c''55"},
       // Degenerate sets: a deviator with zero equivalent stress.
       {"set Yld2004 c'66 = 0\nset Yld2004 c''66 = 0", "Material/Yld2004 c'66"},
       {zero_normal_coefficients(), "Material/Yld2004 c'12"},
       {degenerate_normal_coefficients(), "Material/Yld2004 c'12"}};
  for (const auto &[body, name] : bad)
  {
    MaterialParameters parameters;
    const std::string  message = parse(body, parameters);
    std::cout << "  [" << body << "] -> " << message << std::endl;
    deepdraw_test::check_true("throws InputError naming " + name,
                              message.find(name) != std::string::npos
                                && message.find("allowed")
                                     != std::string::npos);
  }

  // The initial material axes: rotation about z by the rolling direction
  // angle; exact for the default 0 (R0 = I) and for 90 (x and y swapped).
  {
    MaterialParameters parameters;
    const auto         R0 = parameters.initial_material_axes();
    deepdraw_test::check_true(
      "angle 0: R0 = I exactly",
      R0 == dealii::Tensor<2, 3>(dealii::unit_symmetric_tensor<3>()));
    parameters.rolling_direction_angle = 90.;
    const auto R90                     = parameters.initial_material_axes();
    deepdraw_test::check_true("angle 90: rolling direction = y exactly",
                              R90[0][0] == 0. && R90[1][0] == 1.
                                && R90[2][0] == 0. && R90[0][1] == -1.
                                && R90[2][2] == 1.);
    parameters.rolling_direction_angle = 30.;
    const auto R30                     = parameters.initial_material_axes();
    deepdraw_test::check_close("angle 30: rolling direction (cos 30, sin 30)",
                               std::abs(R30[0][0] - std::sqrt(3.) / 2.)
                                 + std::abs(R30[1][0] - 0.5),
                               0.,
                               1e-15);
    deepdraw_test::check_close("angle 30: R^T R = I",
                               (transpose(R30) * R30
                                - dealii::Tensor<2, 3>(
                                  dealii::unit_symmetric_tensor<3>()))
                                 .norm(),
                               0.,
                               1e-15);
    deepdraw_test::check_close("angle 30: det R = 1",
                               determinant(R30),
                               1.,
                               1e-15);
  }

  // Values outside a Pattern are refused by ParameterHandler itself.
  {
    MaterialParameters parameters;
    bool               refused = false;
    try
    {
      parse("set Hill G = -0.1", parameters);
    }
    catch (const dealii::ExceptionBase &)
    {
      refused = true;
    }
    deepdraw_test::check_true("Hill G = -0.1 refused by its Pattern", refused);
    refused = false;
    try
    {
      parse("set Rolling direction angle = 200", parameters);
    }
    catch (const dealii::ExceptionBase &)
    {
      refused = true;
    }
    deepdraw_test::check_true("Rolling direction angle = 200 refused", refused);
  }

  // Parameters set in code are validated by the ElastoPlasticity constructor,
  // NaN and infinity included (a prm cannot give them: the Pattern refuses
  // them).
  {
    MaterialParameters hill, voce, yld2004;
    hill.hill_G           = -0.2;
    voce.voce_A           = std::numeric_limits<double>::quiet_NaN();
    yld2004.yld2004_c2[3] = std::numeric_limits<double>::infinity();
    for (const auto &[parameters, name] :
         {std::make_pair(hill, std::string("Material/Hill G")),
          std::make_pair(voce, std::string("Material/Voce A")),
          std::make_pair(yld2004, std::string("Material/Yld2004 c''23"))})
    {
      std::string message;
      try
      {
        deepdraw::material::ElastoPlasticity material(parameters);
      }
      catch (const deepdraw::InputError &e)
      {
        message = e.what();
      }
      std::cout << "  [constructor] -> " << message << std::endl;
      deepdraw_test::check_true("constructor throws naming " + name,
                                message.find(name) != std::string::npos);
    }
  }
  return deepdraw_test::summary();
}
