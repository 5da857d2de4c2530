// VTU output of a tool: point and cell counts, coordinates at the current
// placement, unit normals.
#include "test_utilities.h"

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>
#include <deepdraw/geometry/square_cup_tools.h>
#include <deepdraw/geometry/tool_vtu.h>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace deepdraw::geometry;
using namespace deepdraw_test;

namespace
{
  // The numbers of the first DataArray at or after `marker`.
  std::vector<double>
  data_array(const std::string &text, const std::string &marker)
  {
    // The DataArray tag containing the marker, or else the next one.
    const auto at  = text.find(marker);
    auto       tag = text.rfind("<DataArray", at);
    if (tag == std::string::npos || text.find('>', tag) < at)
      tag = text.find("<DataArray", at);
    const auto          begin = text.find('>', tag) + 1;
    const auto          end   = text.find("</DataArray>", begin);
    std::istringstream  stream(text.substr(begin, end - begin));
    std::vector<double> values;
    double              value;
    while (stream >> value)
      values.push_back(value);
    return values;
  }
} // namespace

int
main()
{
  auto tools = build_square_cup_tools(SquareCupToolParameters(), 0.81);
  // The punch 12.5 mm down.
  tools[0].set_rigid_motion(dealii::unit_symmetric_tensor<3>(),
                            dealii::Tensor<1, 3>({0., 0., -12.5}));
  const std::string filename
    = (std::filesystem::temp_directory_path()
       / ("deepdraw_punch_" + std::to_string(::getpid()) + ".vtu"))
        .string();
  const unsigned int n = 6;
  write_vtu(tools[0], filename, n);

  std::ifstream     in(filename);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::filesystem::remove(filename);

  const unsigned int n_points = 12 * (n + 1) * (n + 1),
                     n_cells  = 12 * 2 * n * n;
  check_true("header: point and cell counts",
             text.find("NumberOfPoints=\"" + std::to_string(n_points)
                       + "\" NumberOfCells=\"" + std::to_string(n_cells) + "\"")
               != std::string::npos);
  const auto points       = data_array(text, "<Points>");
  const auto normals      = data_array(text, "Name=\"normal\"");
  const auto types        = data_array(text, "Name=\"types\"");
  const auto connectivity = data_array(text, "Name=\"connectivity\"");
  check_true("3 coordinates per point", points.size() == 3 * n_points);
  check_true("3 normal components per point", normals.size() == 3 * n_points);
  if (points.size() != 3 * n_points || normals.size() != 3 * n_points)
    return summary();
  check_true("triangles only",
             types.size() == n_cells
               && std::all_of(types.begin(),
                              types.end(),
                              [](double t) { return t == 5; }));
  check_true("connectivity: 3 valid indices per triangle",
             connectivity.size() == 3 * n_cells
               && *std::max_element(connectivity.begin(), connectivity.end())
                    == n_points - 1);
  double z_min = 1e300, z_max = -1e300, normal_error = 0.;
  for (unsigned int k = 0; k < n_points; ++k)
  {
    z_min        = std::min(z_min, points[3 * k + 2]);
    z_max        = std::max(z_max, points[3 * k + 2]);
    normal_error = std::max(normal_error,
                            std::abs(std::hypot(normals[3 * k],
                                                normals[3 * k + 1],
                                                normals[3 * k + 2])
                                     - 1));
  }
  check_close("lowest point: punch face at t - 12.5", z_min, 0.81 - 12.5, 1e-9);
  check_close("highest point: wall top at t + 50 - 12.5",
              z_max,
              0.81 + 50 - 12.5,
              1e-9);
  check_close("normals of unit length", normal_error, 0., 1e-9);
  return summary();
}
