// libFuzzer target: the tool-file reader (doc/tool_files.md) on arbitrary
// bytes. An input must either be rejected with deepdraw::InputError or give
// a tool whose closest-point projections are finite (gap, foot, normal,
// curvature: what the contact pairs use); any other exception, a
// sanitizer report or a non-finite projection is a bug (abort). Built and
// run by scripts/fuzz.sh, not by ctest.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deepdraw/geometry/rigid_tool.h>
#include <deepdraw/geometry/tool_file.h>
#include <deepdraw/io/input_error.h>
#include <fstream>
#include <iostream>
#include <string>
#include <unistd.h>

namespace
{
  bool
  finite(const dealii::Point<3> &x)
  {
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
  }
} // namespace

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  static const std::string path
    = "fuzz_tool_" + std::to_string(::getpid()) + ".tool";
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char *>(data),
              static_cast<std::streamsize>(size));
  }
  try
  {
    const deepdraw::geometry::RigidTool tool
      = deepdraw::geometry::read_tool_file(path);
    // Points around the first control point and far away, as the contact
    // search would project sheet nodes.
    const dealii::Point<3> first    = tool.patch(0).control_points()[0];
    const dealii::Point<3> points[] = {first + dealii::Point<3>(0., 0., 1.),
                                       first + dealii::Point<3>(-3., 2., -1.),
                                       dealii::Point<3>(0., 0., 0.),
                                       dealii::Point<3>(1e3, -1e3, 1e3)};
    for (const dealii::Point<3> &x : points)
    {
      deepdraw::geometry::ProjectionResult result;
      if (tool.project(x, result, 1e7)
          && !(std::isfinite(result.gap) && std::isfinite(result.distance)
               && finite(result.foot) && finite(dealii::Point<3>(result.normal))
               && std::isfinite(result.curvature.norm())))
      {
        std::cerr << "fuzz: non-finite projection of (" << x
                  << ") onto an accepted tool\n";
        std::abort();
      }
    }
  }
  catch (const deepdraw::InputError &)
  {
  }
  return 0;
}
