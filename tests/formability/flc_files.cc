// flc.csv, flc.gp and flc.png of write_flc_files: the table holds the
// curve's points (a tabulated curve: its nodes; an M-K curve: also the
// strain ratio and the critical groove angle of each point), the picture
// is made by gnuplot where it is installed (else the returned line says
// so and nothing else fails). The CSV holds 10 significant digits, so the
// values read back agree to 5e-11 relative: 1e-9 allowed.
#include "../test_utilities.h"

#include <deepdraw/formability/flc_files.h>
#include <deepdraw/formability/forming_limit_curve_factory.h>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace deepdraw;
namespace fs = std::filesystem;

namespace
{
  std::vector<std::vector<std::string>>
  read_csv(const std::string &filename)
  {
    std::ifstream                         file(filename);
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(file, line);)
    {
      std::istringstream       fields(line);
      std::vector<std::string> row;
      for (std::string field; std::getline(fields, field, ',');)
        row.push_back(field);
      rows.push_back(row);
    }
    return rows;
  }

  void
  check_picture(const std::string &outcome, const std::string &directory)
  {
    std::cout << "  gnuplot: " << outcome << std::endl;
    std::ifstream png(directory + "/flc.png", std::ios::binary);
    char          magic[4] = {};
    png.read(magic, 4);
    const bool written = std::string(magic + 1, 3) == "PNG";
    deepdraw_test::check_true("flc.png written, or gnuplot reported missing",
                              (outcome == "flc.png written" && written)
                                || (outcome.find("gnuplot not found") == 0
                                    && !written));
    deepdraw_test::check_true("flc.gp written",
                              fs::exists(directory + "/flc.gp"));
  }

  void
  check_points(const std::vector<std::vector<std::string>> &rows,
               const std::vector<formability::FlcPoint>    &points,
               const bool                                   mk)
  {
    deepdraw_test::check_true("one row per point",
                              rows.size() == points.size() + 1);
    for (unsigned int k = 0; k + 1 < rows.size() && k < points.size(); ++k)
    {
      deepdraw_test::check_relative("eps2",
                                    std::stod(rows[k + 1][0]),
                                    points[k].minor_strain,
                                    1e-9,
                                    1e-9);
      deepdraw_test::check_relative("eps1",
                                    std::stod(rows[k + 1][1]),
                                    points[k].major_strain,
                                    1e-9);
      if (mk)
        deepdraw_test::check_relative("groove angle",
                                      std::stod(rows[k + 1][3]),
                                      points[k].groove_angle,
                                      1e-9,
                                      1e-9);
    }
  }
} // namespace


int
main()
{
  const std::string directory = "formability_flc_files";
  fs::remove_all(directory);
  fs::create_directories(directory);

  formability::FormabilityParameters parameters;
  parameters.curve_type
    = formability::FormabilityParameters::CurveType::tabulated;
  parameters.table        = {{-0.3, 0.55}, {0., 0.25}, {0.3, 0.4}};
  parameters.table_source = "Formability/Table";
  const material::MaterialParameters material;
  std::string                        outcome
    = formability::write_flc_files(parameters, material, 0.81, directory);
  std::vector<std::vector<std::string>> rows = read_csv(directory + "/flc.csv");
  deepdraw_test::check_true("tabulated: columns eps2, eps1",
                            !rows.empty()
                              && rows[0]
                                   == std::vector<std::string>{"eps2", "eps1"});
  check_points(rows, parameters.table, false);
  check_picture(outcome, directory);

  parameters.curve_type
    = formability::FormabilityParameters::CurveType::marciniak_kuczynski;
  parameters.marciniak_kuczynski.strain_ratio_step = 0.25;
  parameters.marciniak_kuczynski.groove_angle_step = 5.;
  fs::remove(directory + "/flc.png");
  outcome = formability::write_flc_files(parameters, material, 0.81, directory);
  rows    = read_csv(directory + "/flc.csv");
  deepdraw_test::check_true(
    "M-K: columns eps2, eps1, strain_ratio, groove_angle_deg",
    !rows.empty()
      && rows[0]
           == std::vector<std::string>{"eps2",
                                       "eps1",
                                       "strain_ratio",
                                       "groove_angle_deg"});
  check_points(rows,
               formability::create_forming_limit_curve(parameters,
                                                       material,
                                                       0.81)
                 ->points(),
               true);
  check_picture(outcome, directory);
  return deepdraw_test::summary();
}
