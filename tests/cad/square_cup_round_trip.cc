// The square-cup punch, die and blank holder (quarter and full model)
// written as STEP and IGES files from the exact builder (write_cad_tool) and
// read back (read_cad_tool):
// same number of patches, no trimmed face, the same free edges, and at
// 10^4 points per tool around the surface (on the flats, the radii and
// exactly over the patch junctions, both sides of the surface, beyond the
// free edges) the same answer as the built-in tool: found or not, on a
// free edge or not, and gap, foot point and normal within 1e-9 mm. The
// quarter punch written inside out comes back turned towards the sheet.
#include "test_utilities.h"

#include <chrono>
#include <deepdraw/geometry/cad_tool_reader.h>
#include <deepdraw/geometry/cad_tool_writer.h>
#include <deepdraw/geometry/square_cup_tools.h>
#include <filesystem>
#include <random>
#include <unistd.h>

using namespace deepdraw::geometry;
using namespace deepdraw_test;
using dealii::Point;
using Vector = dealii::Tensor<1, 3>;

namespace
{
  const std::filesystem::path directory
    = std::filesystem::temp_directory_path()
      / ("deepdraw_cad_round_trip_" + std::to_string(::getpid()));

  struct Differences
  {
    double       gap = 0., foot = 0., normal = 0.;
    unsigned int n_points = 0, n_found = 0, n_junction = 0, n_curved = 0,
                 n_free = 0, flag_mismatches = 0;
  };

  // 10^4 points near the built-in tool: a random patch, a random (u, v)
  // (every fourth point exactly on a patch edge, i.e. over a junction or a
  // free edge), moved along the normal by -0.4 ... 1.2 mm and sideways by
  // up to 0.5 mm.
  Differences
  compare(const RigidTool &built_in, const RigidTool &cad)
  {
    std::mt19937                           random(2024);
    std::uniform_real_distribution<double> unit(0., 1.);
    Differences                            d;
    const double                           search_distance = 3.;
    for (unsigned int n = 0; n < 10000; ++n)
    {
      const unsigned int k
        = std::min<unsigned int>(unit(random) * built_in.n_patches(),
                                 built_in.n_patches() - 1);
      const BezierPatch &patch = built_in.patch(k);
      double             u = unit(random), v = unit(random);
      const bool         on_junction = n % 4 == 0;
      if (on_junction)
      {
        if (n % 8 == 0)
          u = (n % 16 == 0) ? 0. : 1.;
        else
          v = (n % 16 == 4) ? 0. : 1.;
      }
      const SurfacePoint s      = patch.derivatives(u, v);
      const Vector       normal = unit_normal(s);
      const Vector       side   = s.x_u / s.x_u.norm();
      const Point<3>     x = s.position + (-0.4 + 1.6 * unit(random)) * normal
                         + 0.5 * (unit(random) - 0.5) * side;

      ProjectionResult a, b;
      const bool       found_a = built_in.project(x, a, search_distance);
      const bool       found_b = cad.project(x, b, search_distance);
      ++d.n_points;
      if (found_a != found_b || (found_a && a.on_free_edge != b.on_free_edge))
      {
        ++d.flag_mismatches;
        continue;
      }
      if (!found_a)
        continue;
      ++d.n_found;
      d.n_junction += on_junction;
      d.n_free += a.on_free_edge;
      d.n_curved += std::abs(a.principal_curvatures[0])
                      + std::abs(a.principal_curvatures[1])
                    > 1e-6;
      d.gap    = std::max(d.gap, std::abs(a.gap - b.gap));
      d.foot   = std::max(d.foot, a.foot.distance(b.foot));
      d.normal = std::max(d.normal, (a.normal - b.normal).norm());
    }
    return d;
  }

  unsigned int
  n_free_edges(const RigidTool &tool)
  {
    unsigned int n = 0;
    for (unsigned int k = 0; k < tool.n_patches(); ++k)
      for (unsigned int e = 0; e < 4; ++e)
        n += tool.is_free_edge(k, e);
    return n;
  }
} // namespace


int
main()
{
  std::filesystem::create_directories(directory);
  SquareCupToolParameters quarter, full;
  full.full_model = true;

  for (const bool full_model : {false, true})
    for (const std::string extension : {".step", ".iges"})
      for (const RigidTool &built_in :
           build_square_cup_tools(full_model ? full : quarter, 0.81))
      {
        std::string stem = built_in.name() + (full_model ? "_full" : "");
        std::replace(stem.begin(), stem.end(), ' ', '_');
        const std::string filename = (directory / (stem + extension)).string();
        const auto        start    = std::chrono::steady_clock::now();
        write_cad_tool(built_in, filename);
        CadToolOptions options;
        options.towards_sheet
          = Vector({0., 0., built_in.name() == "die" ? 1. : -1.});
        options.symmetry_plane_x = options.symmetry_plane_y = !full_model;
        CadToolReport   report;
        const RigidTool cad
          = read_cad_tool(filename, built_in.name(), options, &report);
        const double seconds = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start)
                                 .count();
        std::cout << filename << " (" << std::filesystem::file_size(filename)
                  << " bytes, written and read in " << seconds
                  << " s): " << report.summary() << std::endl;

        const std::string what = stem + extension;
        check_true(what + ": same number of patches",
                   cad.n_patches() == built_in.n_patches());
        check_true(what + ": no trimmed face", report.n_trimmed_faces == 0);
        check_true(what + ": same number of free patch edges ("
                     + std::to_string(n_free_edges(built_in)) + ")",
                   n_free_edges(cad) == n_free_edges(built_in));

        const Differences d = compare(built_in, cad);
        std::cout << "  " << d.n_points << " points, " << d.n_found
                  << " found (" << d.n_junction << " over junctions or edges, "
                  << d.n_curved << " on radii, " << d.n_free
                  << " beyond free edges)" << std::endl;
        check_true(what + ": found and free-edge flags agree at every point",
                   d.flag_mismatches == 0);
        check_close(what + ": largest gap difference (mm)", d.gap, 0., 1e-9);
        check_close(what + ": largest foot difference (mm)", d.foot, 0., 1e-9);
        check_close(what + ": largest normal difference", d.normal, 0., 1e-9);
      }
  // The quarter punch written inside out (every patch reversed): automatic
  // normals turn all 12 faces back towards the sheet, and the tool answers
  // as the built-in one; with the normals as in the file the gap of a point
  // inside the punch changes sign.
  {
    const RigidTool built_in = build_square_cup_tools(quarter, 0.81)[0];
    RigidTool       inside_out("punch");
    for (unsigned int k = 0; k < built_in.n_patches(); ++k)
      inside_out.add_patch(built_in.patch(k).reversed_u());
    const std::string filename = (directory / "inside_out.step").string();
    write_cad_tool(inside_out, filename);
    CadToolOptions options;
    options.symmetry_plane_x = options.symmetry_plane_y = true;
    CadToolReport   report;
    const RigidTool cad = read_cad_tool(filename, "punch", options, &report);
    std::cout << filename << ": " << report.summary() << std::endl;
    check_true("inside-out punch: 12 faces reversed",
               report.n_reversed_faces == 12);
    const Differences d = compare(built_in, cad);
    check_true("inside-out punch: same flags", d.flag_mismatches == 0);
    check_close("inside-out punch: largest gap difference (mm)",
                d.gap,
                0.,
                1e-9);
    check_close("inside-out punch: largest normal difference",
                d.normal,
                0.,
                1e-9);

    options.normals             = CadNormals::as_in_file;
    const RigidTool  as_written = read_cad_tool(filename, "punch", options);
    ProjectionResult a, b;
    const Point<3>   x(10., 10., 0.81 + 0.3);
    built_in.project(x, a, 3.);
    as_written.project(x, b, 3.);
    check_close("inside-out punch as in file: the gap changes sign",
                b.gap,
                -a.gap,
                1e-12);
  }

  if (!std::getenv("DEEPDRAW_KEEP_FILES"))
    std::filesystem::remove_all(directory);
  return summary();
}
