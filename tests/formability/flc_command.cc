// run_flc_command (deepdraw --flc FILE.prm, once wired): a prm of the
// program with an M-K curve gives exit code 0 and flc.csv in the output
// directory (the prm's Output/Output directory when none is given); bad
// input gives exit code 2 and writes nothing, not even the directory, with
// one line on stderr that names the parameter.
#include "../test_utilities.h"

#include <deepdraw/app/flc_command.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

using namespace deepdraw;
namespace fs = std::filesystem;

namespace
{
  std::string
  write_prm(const std::string &name, const std::string &formability)
  {
    const std::string filename = "formability_flc_command/" + name + ".prm";
    std::ofstream     prm(filename);
    prm << "subsection Output\n  set Output directory = "
           "formability_flc_command/from_prm\nend\n"
        << "subsection Formability\n"
        << formability << "\nend\n";
    return filename;
  }
} // namespace


int
main()
{
  fs::remove_all("formability_flc_command");
  fs::create_directories("formability_flc_command");
  const std::string mk
    = write_prm("mk",
                "set Forming limit curve = Marciniak-Kuczynski\n"
                "subsection Marciniak-Kuczynski\nset Strain ratio step = 0.5\n"
                "set Groove angle step = 5\nend");
  deepdraw_test::check_true("M-K: exit code 0",
                            app::run_flc_command(mk,
                                                 "formability_flc_command/out")
                              == 0);
  deepdraw_test::check_true("M-K: flc.csv written",
                            fs::exists("formability_flc_command/out/flc.csv"));
  deepdraw_test::check_true("M-K, no directory given: exit code 0",
                            app::run_flc_command(mk, "") == 0);
  deepdraw_test::check_true(
    "M-K, no directory given: flc.csv in Output/Output directory",
    fs::exists("formability_flc_command/from_prm/flc.csv"));

  // Each bad input with a text its message must hold.
  const std::vector<std::pair<std::string, std::string>> bad
    = {{"set Forming limit curve = tabulated\nset Table = 0, 0.3; 0, 0.4",
        "Formability/Table: point 2"},
       {"set Forming limit curve = tabulated", "Formability/Table file"},
       {"set Forming limit curve = Marciniak-Kuczynski\n"
        "subsection Marciniak-Kuczynski\nset Imperfection f0 = 0\nend",
        "Formability/Marciniak-Kuczynski/Imperfection f0"},
       {"set Forming limit curve = Keeler-Brazier", "Material/Swift exponent"},
       {"set Forming limit curve = none", "Formability/Forming limit curve"},
       {"set Forming limit curve = Hill", "Forming limit curve"}};
  for (unsigned int k = 0; k < bad.size(); ++k)
  {
    const std::string  name   = "bad" + std::to_string(k);
    const std::string  output = "formability_flc_command/" + name;
    std::ostringstream messages;
    std::streambuf    *stderr_buffer = std::cerr.rdbuf(messages.rdbuf());
    const int          code
      = app::run_flc_command(write_prm(name, bad[k].first), output);
    std::cerr.rdbuf(stderr_buffer);
    std::cout << "  " << messages.str();
    deepdraw_test::check_true(name + ": exit code 2", code == 2);
    deepdraw_test::check_true(name + ": nothing written", !fs::exists(output));
    deepdraw_test::check_true(
      name + ": one line naming the parameter",
      messages.str().find(bad[k].second) != std::string::npos
        && messages.str().rfind("deepdraw: error in the input: ", 0) == 0
        && messages.str().find('\n') + 1 == messages.str().size());
  }
  return deepdraw_test::summary();
}
