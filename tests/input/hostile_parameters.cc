// Hostile input, class "numeric parameters" (doc/user_guide.md §5.2): every
// numeric entry of every subsection is given nan, inf, -1, 0 and 1e300 on top
// of a coarse square cup, and run through deepdraw's own program function
// (app::run_command_line, what source/main.cc calls), in this process so
// that the ~300 cases take seconds. A rejected value must give exit code 2,
// a message naming the entry, and no output directory; an allowed one must
// pass `--check`. The table must list every Double and Integer entry that
// deepdraw declares (checked against the declarations), so a new parameter
// cannot escape the test.
#include "../test_utilities.h"

// As deal.II does: boost's JSON parser includes boost/bind.hpp, which asks
// for this (a #pragma message otherwise).
#define BOOST_BIND_GLOBAL_PLACEHOLDERS
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#undef BOOST_BIND_GLOBAL_PLACEHOLDERS
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/app/command_line.h>
#include <deepdraw/problem/forming_problem.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  namespace fs = std::filesystem;

  const std::vector<std::string> hostile_values
    = {"nan", "inf", "-1", "0", "1e300"};

  // Every numeric entry, and which of hostile_values it accepts.
  struct Entry
  {
    std::string path;
    std::string allowed; // space-separated subset of hostile_values
  };

  const std::vector<Entry> entries
    = {{"Geometry/Length", ""},
       {"Geometry/Width", ""},
       {"Geometry/Thickness", ""},
       {"Geometry/Elements along x", ""},
       {"Geometry/Elements along y", ""},
       {"Geometry/Layers through thickness", ""},
       {"Geometry/Mesh distortion", "0"},
       // Checked only with Blank outline = circle (the square cup is a
       // rectangle): 0 passes --check there.
       {"Geometry/Diameter", "0"},
       {"Geometry/Elements along radius", ""},
       {"Process/Final load", "0"},
       {"Material/Young's modulus", ""},
       {"Material/Poisson's ratio", "0"},
       {"Material/Hill F", "0"},
       {"Material/Hill G", "0"},
       {"Material/Hill H", "0"},
       {"Material/Hill L", ""},
       {"Material/Hill M", ""},
       {"Material/Hill N", ""},
       // Any Yld2004-18p coefficient may be -1 or 0 alone (the others 1: a
       // bounded yield surface); the exponent is at least 2.
       {"Material/Yld2004 c'12", "-1 0"},
       {"Material/Yld2004 c'13", "-1 0"},
       {"Material/Yld2004 c'21", "-1 0"},
       {"Material/Yld2004 c'23", "-1 0"},
       {"Material/Yld2004 c'31", "-1 0"},
       {"Material/Yld2004 c'32", "-1 0"},
       {"Material/Yld2004 c'44", "-1 0"},
       {"Material/Yld2004 c'55", "-1 0"},
       {"Material/Yld2004 c'66", "-1 0"},
       {"Material/Yld2004 c''12", "-1 0"},
       {"Material/Yld2004 c''13", "-1 0"},
       {"Material/Yld2004 c''21", "-1 0"},
       {"Material/Yld2004 c''23", "-1 0"},
       {"Material/Yld2004 c''31", "-1 0"},
       {"Material/Yld2004 c''32", "-1 0"},
       {"Material/Yld2004 c''44", "-1 0"},
       {"Material/Yld2004 c''55", "-1 0"},
       {"Material/Yld2004 c''66", "-1 0"},
       {"Material/Yld2004 exponent", ""},
       {"Material/Swift coefficient", ""},
       {"Material/Swift prestrain", ""},
       {"Material/Swift exponent", "0"},
       {"Material/Voce A", ""},
       {"Material/Voce B", "0"},
       {"Material/Voce C", "0"},
       {"Material/Prager modulus", "0"},
       {"Material/Rolling direction angle", "-1 0"},
       {"Finite element/Enhanced tolerance", ""},
       {"Finite element/Enhanced iterations", ""},
       {"Finite element/Points through the thickness", ""},
       {"Load stepping/Initial increment", ""},
       {"Load stepping/Minimum increment", "0"},
       {"Load stepping/Maximum increment", ""},
       {"Load stepping/Cut-back factor", ""},
       {"Load stepping/Growth factor", ""},
       {"Load stepping/Easy increment iterations", ""},
       {"Load stepping/Maximum cut-backs", "0"},
       {"Newton/Maximum iterations", ""},
       {"Newton/Minimum iterations", "0"},
       {"Newton/Force tolerance", ""},
       {"Newton/Correction tolerance", ""},
       {"Newton/Divergence ratio", ""},
       {"Newton/Line search steps", "0"},
       {"Newton/Full step state changes", "0"},
       {"Newton/Stagnation iterations", "0"},
       {"Newton/Stagnation residual", "0"},
       {"Newton/Tool force tolerance", "0"},
       {"Linear solver/Forcing term", ""},
       {"Linear solver/Smallest forcing term", ""},
       {"Linear solver/Reuse iterations", ""},
       {"Linear solver/Reuse threshold", ""},
       {"Linear solver/Single precision tolerance", ""},
       {"Linear solver/AMG tolerance", ""},
       {"Linear solver/AMG iterations", ""},
       {"Linear solver/AMG coarse size", ""},
       {"Output/Output interval", "0"},
       {"Checkpoint/Interval", "0"},
       {"Adaptivity/Refinement interval", ""},
       {"Adaptivity/Maximum level", "0"},
       {"Adaptivity/Maximum number of cells", ""},
       {"Adaptivity/Jump threshold", "0"},
       {"Adaptivity/Curvature threshold", ""},
       {"Output/Thickness profile travels", "0"},
       {"Postprocess/Section profile/Number of points", ""},
       {"Contact/Friction coefficient", "0"},
       {"Contact/Augmentation parameter", "0"},
       {"Contact/Augmentation scaling", ""},
       {"Contact/Search distance", ""},
       // 0 is the default of the tools that are not spring-backed.
       {"Contact/Tool 1/Spring stiffness", "0"},
       {"Contact/Tool 2/Spring stiffness", "0"},
       {"Contact/Tool 3/Spring stiffness", "0"},
       {"Contact/Tool 4/Spring stiffness", "0"},
       {"Tools/Punch/Half width", ""},
       {"Tools/Punch/Plan corner radius", ""},
       {"Tools/Punch/Profile radius", ""},
       {"Tools/Punch/Height", ""},
       {"Tools/Punch/Initial gap", "0"},
       {"Tools/Die/Opening half width", ""},
       {"Tools/Die/Plan corner radius", ""},
       {"Tools/Die/Shoulder radius", ""},
       {"Tools/Die/Depth", ""},
       {"Tools/Die/Outer half width", ""},
       {"Tools/Blank holder/Outer half width", ""},
       {"Tools/Blank holder/Initial gap", "0"},
       // Subsection Formability is parsed only when the post-processor
       // "forming limits" is listed, which the square cup here does not:
       // what its Pattern accepts passes --check. The values that the
       // post-processor refuses (f0 = 0, a thinning limit of 0, ...) are
       // cases of tests/input/hostile_cases.py, class formability.
       {"Formability/Safety band", "0"},
       {"Formability/Thinning limit", "-1 0"},
       {"Formability/Insufficient stretch strain", "0"},
       {"Formability/Wrinkling minor strain", "0"},
       {"Formability/FLD travels", "0"},
       {"Formability/Marciniak-Kuczynski/Imperfection f0", "0"},
       {"Formability/Marciniak-Kuczynski/Groove angle step", "0"},
       {"Formability/Marciniak-Kuczynski/Strain increment", "0"},
       {"Formability/Marciniak-Kuczynski/Localisation factor", ""},
       {"Formability/Marciniak-Kuczynski/Strain ratio step", "0"}};

  // Values beyond the five above that a bound or a check across entries
  // must catch (D50, D53): path, value, a part of the message.
  struct Extra
  {
    std::string path, value, message;
  };
  const std::vector<Extra> extras
    = {{"Geometry/Elements along x", "100000", "GB of memory"},
       {"Geometry/Length", "10001", "Length"},
       {"Geometry/Thickness", "1e-400", "Thickness"},
       {"Contact/Search distance", "200", "diagonal of the blank"},
       {"Output/Output interval", "1e-9", "VTU files"},
       {"Load stepping/Maximum increment", "1e-9", "increments"},
       {"Output/Thickness profile travels",
        "1, 1.0000000001",
        "both give the file name thickness_OX_1mm.csv"},
       {"Material/Young's modulus", "2e7", "Young's modulus"},
       {"Material/Poisson's ratio", "0.5", "Poisson's ratio"},
       {"Material/Swift coefficient", "1e16", "Swift coefficient"},
       {"Material/Hill G", "0\n set Hill H = 0", "Hill G"},
       {"Material/Yld2004 exponent", "1.5", "Yld2004 exponent"},
       {"Material/Yld2004 c'66", "0\n set Yld2004 c''66 = 0", "Yld2004 c'66"},
       {"Material/Voce B", "500", "Voce B"},
       {"Material/Hardening table", "0:100, 0.1:90", "Hardening table"},
       {"Material/Hardening table", "0:100, 0.1", "Hardening table"},
       {"Newton/Force tolerance", "1", "Force tolerance"},
       {"Newton/Minimum iterations", "41", "Minimum iterations"},
       {"Contact/Friction coefficient", "10.5", "Friction coefficient"},
       {"Linear solver/Reuse iterations", "automatic", "Reuse iterations"},
       {"Geometry/Elements along x", "2147483648", "Elements along x"},
       {"Geometry/Elements along x", "1.5", "Elements along x"},
       {"Geometry/Length", "75 mm", "Length"},
       {"Geometry/Length", "", "Length"},
       {"Geometry/Length", "0x10", "Length"},
       // Control = spring needs a stiffness > 0 (D187): the default 0.
       {"Contact/Tool 3/Control", "spring", "Spring stiffness"}};

  // The repository root, from CMake (tests/CMakeLists.txt): __FILE__ may be
  // relative to wherever the compiler (or ccache) ran.
  const fs::path repository = DEEPDRAW_SOURCE_DIR;

  std::vector<std::string>
  split_path(const std::string &path)
  {
    std::vector<std::string> parts;
    std::istringstream       in(path);
    std::string              part;
    while (std::getline(in, part, '/'))
      parts.push_back(part);
    return parts;
  }

  // The coarse square cup (6 x 6 x 1 cells, with its three tools) and the
  // entry set to value.
  std::string
  prm_text(const std::string &path, const std::string &value)
  {
    std::string text = "include "
                       + (repository / "prm" / "square_cup.prm").string()
                       + "\nsubsection Geometry\n  set Elements along x = 6\n"
                         "  set Elements along y = 6\n"
                         "  set Layers through thickness = 1\nend\n"
                         "subsection Process\n  set Final load = 0.5\nend\n";
    const std::vector<std::string> parts = split_path(path);
    for (std::size_t k = 0; k + 1 < parts.size(); ++k)
      text += "subsection " + parts[k] + "\n";
    text += "  set " + parts.back() + " = " + value + "\n";
    for (std::size_t k = 0; k + 1 < parts.size(); ++k)
      text += "end\n";
    return text;
  }

  // Runs the program on the text; returns the exit code, stderr in errors.
  int
  run(const std::string              &text,
      const std::vector<std::string> &arguments,
      std::string                    &errors)
  {
    {
      std::ofstream out("case.prm");
      out << text;
    }
    std::ostringstream captured_out, captured_err;
    std::streambuf    *saved_out = std::cout.rdbuf(captured_out.rdbuf());
    std::streambuf    *saved_err = std::cerr.rdbuf(captured_err.rdbuf());
    int                code      = -1;
    try
    {
      code = deepdraw::app::run_command_line(arguments);
    }
    catch (...)
    {
      code = -2; // an exception escaped the program: a bug
    }
    std::cout.rdbuf(saved_out);
    std::cerr.rdbuf(saved_err);
    errors = captured_err.str();
    return code;
  }

  void
  check_case(const std::string &path,
             const std::string &value,
             const bool         allowed,
             const std::string &message)
  {
    const fs::path output = "case_output";
    fs::remove_all(output);
    std::string       errors;
    const std::string label = path + " = " + value;
    if (allowed)
    {
      const int code
        = run(prm_text(path, value), {"--check", "case.prm"}, errors);
      deepdraw_test::check_true(label + ": accepted by --check (exit "
                                  + std::to_string(code) + ")"
                                  + (code == 0 ? "" : ": " + errors),
                                code == 0);
    }
    else
    {
      const int  code = run(prm_text(path, value),
                           {"case.prm", "--output-directory", output.string()},
                           errors);
      const bool one_line
        = !errors.empty() && errors.find('\n') == errors.size() - 1;
      deepdraw_test::check_true(label + ": exit 2 (got " + std::to_string(code)
                                  + "), one line naming '" + message
                                  + "', no "
                                    "output directory: "
                                  + errors.substr(0, 300),
                                code == 2 && one_line
                                  && errors.find(message) != std::string::npos
                                  && !fs::exists(output));
    }
  }

  // Every entry whose pattern is a Double, an Integer or a list of them.
  void
  collect_numeric(const boost::property_tree::ptree &tree,
                  const std::string                 &prefix,
                  std::set<std::string>             &paths)
  {
    for (const auto &[name, child] : tree)
    {
      const auto pattern
        = child.get_optional<std::string>("pattern_description");
      if (pattern)
      {
        if (pattern->find("[Double") != std::string::npos
            || pattern->find("[Integer") != std::string::npos)
          paths.insert(prefix + name);
      }
      else if (!child.empty())
        collect_numeric(child, prefix + name + "/", paths);
    }
  }
} // namespace


int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::deal_II_exceptions::disable_abort_on_exception();
  // A directory of its own: ctest runs tests in parallel in one directory.
  fs::create_directories("hostile_parameters");
  fs::current_path("hostile_parameters");

  // The table covers every numeric entry.
  {
    dealii::ParameterHandler prm;
    deepdraw::problem::FormingProblem::declare_parameters(prm);
    std::stringstream json;
    prm.print_parameters(json, dealii::ParameterHandler::JSON);
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(json, tree);
    std::set<std::string> declared, listed;
    collect_numeric(tree, "", declared);
    for (const Entry &entry : entries)
      listed.insert(entry.path);
    for (const std::string &path : declared)
      deepdraw_test::check_true("numeric entry " + path + " is in the table",
                                listed.count(path) == 1);
    for (const std::string &path : listed)
      deepdraw_test::check_true("table entry " + path + " is declared",
                                declared.count(path) == 1);
  }

  unsigned int n_cases = 0;
  for (const Entry &entry : entries)
    for (const std::string &value : hostile_values)
    {
      const bool allowed = (" " + entry.allowed + " ").find(" " + value + " ")
                           != std::string::npos;
      check_case(entry.path, value, allowed, split_path(entry.path).back());
      ++n_cases;
    }
  for (const Extra &extra : extras)
  {
    check_case(extra.path, extra.value, false, extra.message);
    ++n_cases;
  }
  std::cout << n_cases << " cases" << std::endl;
  return deepdraw_test::summary();
}
