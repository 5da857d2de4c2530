// Tool files: every malformed file gives an InputError naming the file and
// the line; a missing file names the file; write → read is exact.
#include "test_utilities.h"

#include <cmath>
#include <deepdraw/geometry/square_cup_tools.h>
#include <deepdraw/geometry/tool_file.h>
#include <deepdraw/io/input_error.h>
#include <filesystem>
#include <fstream>
#include <random>

using namespace deepdraw::geometry;
using namespace deepdraw_test;
using dealii::Point;

namespace
{
  const std::filesystem::path directory
    = std::filesystem::temp_directory_path()
      / ("deepdraw_tool_file_test_" + std::to_string(::getpid()));

  // A good bilinear patch block.
  const std::string good_patch = "patch\n"
                                 "degrees 1 1\n"
                                 "0 0 0 1\n"
                                 "1 0 0 1\n"
                                 "0 1 0 1\n"
                                 "1 1 0 1\n"
                                 "end\n";

  // Writes `content` to name.tool, reads it and checks that the error
  // message contains every expected piece.
  void
  expect_error(const std::string              &name,
               const std::string              &content,
               const std::vector<std::string> &expected)
  {
    const std::string filename = (directory / (name + ".tool")).string();
    {
      std::ofstream out(filename);
      out << content;
    }
    std::string message = "(no error)";
    try
    {
      read_tool_file(filename);
    }
    catch (const deepdraw::InputError &error)
    {
      message = error.what();
    }
    bool ok = true;
    for (const std::string &piece : expected)
      ok = ok && message.find(piece) != std::string::npos;
    std::cout << "  " << name << " -> " << message << std::endl;
    check_true(name + ": message has file:line and the reason", ok);
  }

  bool
  identical(const RigidTool &a, const RigidTool &b)
  {
    if (a.name() != b.name() || a.n_patches() != b.n_patches())
      return false;
    for (unsigned int k = 0; k < a.n_patches(); ++k)
    {
      const BezierPatch &p = a.patch(k), &q = b.patch(k);
      if (p.degree_u() != q.degree_u() || p.degree_v() != q.degree_v()
          || p.weights() != q.weights()
          || a.declared_edge_kinds(k) != b.declared_edge_kinds(k))
        return false;
      for (unsigned int n = 0; n < p.control_points().size(); ++n)
        for (unsigned int d = 0; d < 3; ++d)
          if (p.control_points()[n][d]
              != q.control_points()[n][d]) // bitwise-exact
            return false;
      for (unsigned int e = 0; e < 4; ++e)
        if (a.is_free_edge(k, e) != b.is_free_edge(k, e))
          return false;
    }
    return true;
  }
} // namespace

int
main()
{
  std::filesystem::create_directories(directory);
  const std::string d = directory.string() + "/";

  // Missing file.
  {
    std::string message;
    try
    {
      read_tool_file(d + "no_such.tool");
    }
    catch (const deepdraw::InputError &error)
    {
      message = error.what();
    }
    std::cout << "  missing -> " << message << std::endl;
    check_true("missing file: message names the file",
               message.find(d + "no_such.tool: cannot open")
                 != std::string::npos);
  }

  expect_error("not_a_number",
               "# a comment\ntool t\npatch\ndegrees 1 1\n0 0 0 1\n1.0 abc 0 "
               "1\n0 1 0 1\n1 1 0 1\nend\n",
               {"not_a_number.tool:6: expected 3 coordinates and a weight, "
                "found \"1.0 abc 0 1\""});
  expect_error("three_numbers",
               "patch\ndegrees 1 1\n0 0 0 1\n1 0 0\n",
               {"three_numbers.tool:4: expected 3 coordinates and a weight, "
                "found \"1 0 0\""});
  expect_error("five_numbers",
               "patch\ndegrees 1 1\n0 0 0 1 7\n",
               {"five_numbers.tool:3: expected 3 coordinates and a weight, "
                "found \"0 0 0 1 7\""});
  expect_error(
    "trailing_garbage",
    "patch\ndegrees 1 1\n0 0 0 1x\n",
    {"trailing_garbage.tool:3: expected 3 coordinates and a weight"});
  expect_error("zero_weight",
               "patch\ndegrees 1 1\n0 0 0 1\n1 0 0 0\n",
               {"zero_weight.tool:4: weights must be positive, found 0"});
  expect_error(
    "negative_weight",
    "\n\npatch\ndegrees 1 1\n0 0 0 -0.5 # bad\n",
    {"negative_weight.tool:5: weights must be positive, found -0.5"});
  expect_error("not_finite",
               "patch\ndegrees 1 1\n0 nan 0 1\n",
               {"not_finite.tool:3: expected finite numbers"});
  expect_error("degree_too_high_for_data",
               "patch\ndegrees 3 3\n0 0 0 1\n1 0 0 1\n0 1 0 1\n1 1 0 1\nend\n",
               {"degree_too_high_for_data.tool:7: degrees 3 3 need 16 control "
                "points (4 x 4), found 4"});
  expect_error("too_many_points",
               good_patch.substr(0, good_patch.size() - 4) + "2 2 0 1\nend\n",
               {"too_many_points.tool:7: degrees 1 1 need 4 control points; "
                "this is one more"});
  expect_error("degree_not_integer",
               "patch\ndegrees 2 x\n",
               {"degree_not_integer.tool:2: expected two degrees (integers), "
                "found \"degrees 2 x\""});
  expect_error("degree_zero",
               "patch\ndegrees 0 1\n",
               {"degree_zero.tool:2: degrees must be at least 1"});
  expect_error("degree_above_maximum",
               "patch\ndegrees 40 1\n",
               {"degree_above_maximum.tool:2: degrees above the maximum 15"});
  expect_error("point_before_degrees",
               "patch\n0 0 0 1\n",
               {"point_before_degrees.tool:2: control point before the patch's "
                "'degrees' line"});
  expect_error(
    "missing_end",
    "tool t\n" + good_patch.substr(0, good_patch.size() - 4),
    {"missing_end.tool:7: the patch started at line 2 has no 'end'"});
  expect_error("patch_inside_patch",
               "patch\ndegrees 1 1\npatch\n",
               {"patch_inside_patch.tool:3: the patch started at line 1 has no "
                "'end' before this 'patch'"});
  expect_error(
    "unknown_keyword",
    good_patch + "surface\n",
    {"unknown_keyword.tool:8: expected 'tool' or 'patch', found \"surface\""});
  expect_error("bad_edges",
               "patch\ndegrees 1 1\nedges free free open free\n",
               {"bad_edges.tool:3: expected 'edges' and four of automatic, "
                "free, shared, symmetry"});
  expect_error("empty",
               "# only a comment\n\n",
               {"empty.tool:2: no patch in the tool file"});
  expect_error(
    "late_tool_name",
    good_patch + "tool late\n",
    {"late_tool_name.tool:8: 'tool' must appear once, before the first patch"});
  expect_error(
    "no_degrees",
    "patch\nend\n",
    {"no_degrees.tool:2: the patch started at line 1 has no 'degrees'"});

  // A good file with comments, name and edges.
  {
    const std::string filename = d + "good.tool";
    std::ofstream(filename) << "# test\ntool my tool  # comment\n"
                            << good_patch.substr(0, good_patch.size() - 4)
                            << "edges free shared automatic symmetry\nend\n";
    const RigidTool tool = read_tool_file(filename);
    check_true("good file: name with a space", tool.name() == "my tool");
    check_true("good file: one bilinear patch",
               tool.n_patches() == 1 && tool.patch(0).degree_u() == 1);
    check_true("good file: edges as declared",
               tool.is_free_edge(0, 0) && !tool.is_free_edge(0, 1)
                 && tool.is_free_edge(0, 2) && !tool.is_free_edge(0, 3));
  }

  // The example of doc/tool_files.md: parses, normal towards the sheet
  // (down, away from the punch), a quarter circle of radius 8.
  {
    const std::string filename = d + "doc_example.tool";
    std::ofstream(filename)
      << "# deepdraw tool file: '#' starts a comment, anywhere on a line\n"
         "tool punch        # optional, once, before the first patch; may "
         "contain spaces\n"
         "patch             # one block per patch; here the punch nose along x "
         "(radius 8)\n"
         "degrees 2 1       # p (u direction) and q (v direction), 1..15\n"
         "# (p+1)(q+1) lines \"x y z weight\", u index running fastest:\n"
         "# line i + (p+1) j holds P_ij\n"
         "35 0 8.81 1\n35 0 0.81 0.70710678118654757\n27 0 0.81 1\n"
         "35 25 8.81 1\n35 25 0.81 0.70710678118654757\n27 25 0.81 1\n"
         "# optional (default: all automatic); order u=0 u=1 v=0 v=1\n"
         "edges automatic automatic symmetry automatic\nend\n";
    const RigidTool tool = read_tool_file(filename);
    const Point<3>  x    = tool.patch(0).value(0.5, 0.3);
    check_close("doc example: radius 8 about the tube axis",
                std::hypot(x[0] - 27, x[2] - 8.81),
                8.,
                1e-12);
    check_true("doc example: normal points away from the punch (x - 27, z - "
               "8.81 direction)",
               tool.patch(0).unit_normal(0.5, 0.3)
                   * (x - Point<3>(27, x[1], 8.81))
                 > 7.99);
  }

  // Round trip of the square-cup tools (quarter and full) and of a random
  // rational patch whose numbers need all 17 digits (a perturbed grid: a
  // net that folds over is rejected by the reader).
  {
    SquareCupToolParameters parameters;
    std::vector<RigidTool>  tools = build_square_cup_tools(parameters, 0.81);
    parameters.full_model         = true;
    for (RigidTool &tool : build_square_cup_tools(parameters, 0.81))
    {
      RigidTool renamed(tool.name() + " full");
      for (unsigned int k = 0; k < tool.n_patches(); ++k)
        renamed.add_patch(tool.patch(k), tool.declared_edge_kinds(k));
      tools.push_back(renamed);
    }
    std::mt19937                           rng(3);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    std::vector<Point<3>>                  points;
    std::vector<double>                    weights;
    for (unsigned int n = 0; n < 12; ++n)
    {
      const unsigned int i = n % 4, j = n / 4;
      points.emplace_back((i + 0.2 * uniform(rng)) * 1e3 / 3.,
                          (j + 0.2 * uniform(rng)) * 10.,
                          uniform(rng) / 3.);
      weights.push_back(1.5 + uniform(rng));
    }
    RigidTool random("random");
    random.add_patch(BezierPatch(3, 2, points, weights));
    tools.push_back(random);

    const auto filenames = write_tool_files(tools, d + "written");
    check_true("write_tool_files: one file per tool, blank_holder.tool for "
               "'blank holder'",
               filenames.size() == tools.size()
                 && filenames[2] == d + "written/blank_holder.tool");
    for (unsigned int t = 0; t < tools.size(); ++t)
      check_true("round trip exact: " + tools[t].name(),
                 identical(tools[t], read_tool_file(filenames[t])));
  }

  std::filesystem::remove_all(directory);
  return summary();
}
