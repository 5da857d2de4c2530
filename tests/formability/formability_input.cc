// Bad input of subsection Formability: each case is a prm read as the
// program reads it (io::read_parameter_file, then parse_parameters, then
// the curve), and must raise deepdraw::InputError whose message names the
// parameter (or file) and the allowed values: an FLC that is not a function
// of eps2, negative or non-finite values, f0 outside (0, 1], an empty
// table, the other checks of formability_parameters.cc, and materials that
// no curve can be computed from (a hardening law without hardening for the
// M-K analysis, no Swift exponent for Keeler-Brazier, D170).
#include "../test_utilities.h"

#include <deal.II/base/parameter_handler.h>
#include <deepdraw/formability/forming_limit_curve_factory.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/parameter_file.h>
#include <fstream>

using namespace deepdraw;

namespace
{
  // The curve of a prm with the given lines in subsection Formability.
  void
  make_curve(const std::string &lines, const material::MaterialParameters &m)
  {
    {
      std::ofstream prm("formability_input.prm");
      prm << "subsection Formability\n" << lines << "\nend\n";
    }
    dealii::ParameterHandler prm;
    prm.enter_subsection("Formability");
    formability::FormabilityParameters::declare_parameters(prm);
    prm.leave_subsection();
    io::read_parameter_file(prm, "formability_input.prm");
    formability::FormabilityParameters parameters;
    prm.enter_subsection("Formability");
    parameters.parse_parameters(prm, ".");
    prm.leave_subsection();
    formability::create_forming_limit_curve(parameters, m, 0.81);
  }

  void
  expect_error(const std::string                  &what,
               const std::string                  &lines,
               const std::vector<std::string>     &expected,
               const material::MaterialParameters &m = {})
  {
    std::string message = "no error";
    try
    {
      make_curve(lines, m);
    }
    catch (const InputError &error)
    {
      message = error.what();
    }
    bool found = true;
    for (const std::string &text : expected)
      found = found && message.find(text) != std::string::npos;
    std::cout << "  " << what << ": " << message << std::endl;
    deepdraw_test::check_true(what + ": InputError naming the parameter",
                              found);
  }
} // namespace


int
main()
{
  const std::string tabulated = "set Forming limit curve = tabulated\n";
  expect_error("not a function of eps2",
               tabulated + "set Table = -0.2, 0.4; 0, 0.3; 0, 0.32",
               {"Formability/Table", "point 3", "increase strictly"});
  expect_error("decreasing eps2",
               tabulated + "set Table = 0.1, 0.4; -0.1, 0.3",
               {"Formability/Table", "increase strictly"});
  expect_error("negative major strain",
               tabulated + "set Table = -0.2, 0.4; 0, -0.3",
               {"Formability/Table", "eps1 > 0"});
  expect_error("non-finite value",
               tabulated + "set Table = -0.2, nan; 0, 0.3",
               {"Formability/Table", "not finite"});
  expect_error("infinite value",
               tabulated + "set Table = -0.2, 0.4; inf, 0.3",
               {"Formability/Table", "not finite"});
  expect_error("empty table", tabulated, {"Formability/Table", "empty"});
  expect_error("a single point",
               tabulated + "set Table = 0, 0.3",
               {"Formability/Table", "at least 2 points"});
  expect_error("not a pair",
               tabulated + "set Table = 0, 0.3, 0.4; 0.1, 0.5",
               {"Formability/Table", "'eps2, eps1'"});
  expect_error("table and file",
               tabulated
                 + "set Table = 0, 0.3; 0.1, 0.4\nset Table file = x.csv",
               {"Formability/Table file", "only one"});
  {
    std::ofstream file("formability_bad_table.csv");
    file << "eps2,eps1\n-0.1,0.4\n0 0.3 extra\n";
  }
  expect_error("bad line in a table file",
               tabulated + "set Table file = formability_bad_table.csv",
               {"formability_bad_table.csv:3", "two numbers"});
  expect_error("missing table file",
               tabulated + "set Table file = formability_missing.csv",
               {"formability_missing.csv"});
  const std::string mk = "set Forming limit curve = Marciniak-Kuczynski\n"
                         "subsection Marciniak-Kuczynski\n";
  expect_error("f0 = 0",
               mk + "set Imperfection f0 = 0\nend",
               {"Formability/Marciniak-Kuczynski/Imperfection f0",
                "0 < f0 <= 1"});
  expect_error("f0 = 1.5 (the pattern)",
               mk + "set Imperfection f0 = 1.5\nend",
               {"Imperfection f0", "0...1"});
  expect_error("f0 = nan (the pattern)",
               mk + "set Imperfection f0 = nan\nend",
               {"Imperfection f0"});
  expect_error("negative strain increment",
               mk + "set Strain increment = -0.001\nend",
               {"Strain increment"});
  expect_error("localisation factor 1",
               mk + "set Localisation factor = 1\nend",
               {"Formability/Marciniak-Kuczynski/Localisation factor",
                "1 < factor"});
  expect_error("f0 = 1: no localisation",
               mk + "set Imperfection f0 = 1\nset Strain increment = 0.01\nend",
               {"Imperfection f0", "f0 < 1"});
  material::MaterialParameters perfectly_plastic;
  perfectly_plastic.swift_exponent = 0.;
  expect_error("M-K without hardening",
               mk + "end",
               {"Material/Swift exponent", "n > 0"},
               perfectly_plastic);
  material::MaterialParameters flat_voce;
  flat_voce.hardening_law = material::HardeningLawType::voce;
  flat_voce.voce_B        = 0.;
  expect_error("M-K with a Voce law without hardening",
               mk + "end",
               {"Material/Voce B", "B > 0 and C > 0"},
               flat_voce);
  material::MaterialParameters flat_table;
  flat_table.hardening_law   = material::HardeningLawType::tabulated;
  flat_table.hardening_table = {{0., 200.}, {0.1, 200.}};
  expect_error("M-K with a flat hardening table",
               mk + "end",
               {"Material/Hardening table", "perfectly plastic"},
               flat_table);
  material::MaterialParameters voce;
  voce.hardening_law = material::HardeningLawType::voce;
  expect_error("Keeler-Brazier n from a Voce material",
               "set Forming limit curve = Keeler-Brazier",
               {"Formability/Keeler-Brazier n", "not Swift", "0 < n <= 0.21"},
               voce);
  expect_error("safety band 100",
               "set Safety band = 100",
               {"Formability/Safety band", "0 <= band < 100"});
  expect_error("thinning limit 0",
               "set Thinning limit = 0",
               {"Formability/Thinning limit", "< 0"});
  expect_error("Keeler-Brazier n not a number",
               "set Forming limit curve = Keeler-Brazier\n"
               "set Keeler-Brazier n = abc",
               {"Formability/Keeler-Brazier n", "a number, or empty"});
  expect_error("Keeler-Brazier with the aluminium's n",
               "set Forming limit curve = Keeler-Brazier",
               {"Material/Swift exponent", "0 < n <= 0.21"});
  expect_error("Keeler-Brazier n negative",
               "set Forming limit curve = Keeler-Brazier\n"
               "set Keeler-Brazier n = -0.1",
               {"Formability/Keeler-Brazier n", "0 < n <= 0.21"});
  expect_error("Keeler-Brazier thickness 4 mm",
               "set Forming limit curve = Keeler-Brazier\n"
               "set Keeler-Brazier n = 0.2\nset Keeler-Brazier thickness = 4",
               {"Formability/Keeler-Brazier thickness", "0 < t <= 3"});

  // A valid table is accepted, and a table is not read unless used.
  bool accepted = true;
  try
  {
    make_curve(tabulated + "set Table = -0.2, 0.4; 0, 0.3", {});
    make_curve("set Table = nonsense", {});
  }
  catch (const InputError &error)
  {
    std::cout << error.what() << std::endl;
    accepted = false;
  }
  deepdraw_test::check_true("valid input accepted", accepted);
  return deepdraw_test::summary();
}
