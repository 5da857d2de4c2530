#include <algorithm>
#include <charconv>
#include <cmath>
#include <deepdraw/geometry/tool_file.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/output_file.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/text_file.h>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

namespace deepdraw::geometry
{
  namespace
  {
    // Limits of the numbers of a tool file (doc/tool_files.md, D50): every
    // product the projection forms stays far from overflow and underflow.
    constexpr double max_coordinate      = 1e6;
    constexpr double min_weight          = 1e-6;
    constexpr double max_weight          = 1e6;
    constexpr double min_extent          = 1e-9;
    constexpr double min_relative_extent = 1e-9;

    std::vector<std::string>
    split(const std::string &text)
    {
      std::istringstream       stream(text);
      std::vector<std::string> tokens;
      std::string              token;
      while (stream >> token)
        tokens.push_back(token);
      return tokens;
    }

    std::string
    trim(const std::string &text)
    {
      const auto first = text.find_first_not_of(" \t\r\n");
      if (first == std::string::npos)
        return "";
      const auto last = text.find_last_not_of(" \t\r\n");
      return text.substr(first, last - first + 1);
    }

    // The whole token must be a number (std::from_chars: no locale, exact
    // round trip of max_digits10 output).
    bool
    parse_double(const std::string &token, double &value)
    {
      const char *begin = token.data();
      const char *end   = token.data() + token.size();
      if (begin != end && *begin == '+')
        ++begin;
      const auto [stop, error] = std::from_chars(begin, end, value);
      return error == std::errc() && stop == end && begin != end;
    }

    bool
    parse_degree(const std::string &token, unsigned int &value)
    {
      const auto [stop, error]
        = std::from_chars(token.data(), token.data() + token.size(), value);
      return error == std::errc() && stop == token.data() + token.size();
    }

    bool
    parse_edge_kind(const std::string &token, EdgeKind &kind)
    {
      for (const EdgeKind candidate : {EdgeKind::automatic,
                                       EdgeKind::free,
                                       EdgeKind::shared,
                                       EdgeKind::symmetry})
        if (token == to_string(candidate))
        {
          kind = candidate;
          return true;
        }
      return false;
    }

    // Collects one "patch ... end" block.
    struct PatchBlock
    {
      unsigned int                  first_line  = 0;
      bool                          has_degrees = false;
      bool                          has_edges   = false;
      unsigned int                  p = 0, q = 0;
      std::vector<dealii::Point<3>> points;
      std::vector<double>           weights;
      RigidTool::EdgeKinds          edges = {{EdgeKind::automatic,
                                              EdgeKind::automatic,
                                              EdgeKind::automatic,
                                              EdgeKind::automatic}};

      std::size_t
      n_expected() const
      {
        return std::size_t(p + 1) * (q + 1);
      }
    };

    // Why a patch cannot be used, or "" (doc/tool_files.md, "Errors"): its
    // control points span no extent; or, on an (N + 1) x (N + 1) grid of
    // (u, v) with N = 2 max(p, q) + 6, edges and corners included, x_u x x_v
    // vanishes at a point (no normal there: a line, a collapsed edge or
    // corner) or turns by more than 90 degrees between neighbouring points
    // (the patch folds over: the normal flips across a line where it is
    // undefined). A sheet node projected onto such a point would get a NaN
    // gap; a node far away is projected onto a corner. Both were found by
    // fuzz/tool_file_fuzzer.cc.
    std::string
    degenerate_patch(const BezierPatch &patch)
    {
      const dealii::BoundingBox<3> &box = patch.bounding_box();
      const double extent = box.get_boundary_points().first.distance(
        box.get_boundary_points().second);
      if (!(extent > min_relative_extent * patch.length_scale())
          || !(extent > min_extent))
        return "all its control points are equal (their extent is below 1e-9 "
               "mm or 1e-9 of their coordinates)";

      const unsigned int n
        = 2 * std::max(patch.degree_u(), patch.degree_v()) + 6;
      const double                      tiny = 1e-10 * extent * extent;
      std::vector<dealii::Tensor<1, 3>> normal((n + 1) * (n + 1));
      const auto at = [&](const unsigned int i, const unsigned int j)
      {
        std::ostringstream text;
        text << "(u, v) = (" << double(i) / n << ", " << double(j) / n << ")";
        return text.str();
      };
      std::vector<double> area((n + 1) * (n + 1));
      for (unsigned int j = 0; j <= n; ++j)
        for (unsigned int i = 0; i <= n; ++i)
        {
          const SurfacePoint x
            = patch.derivatives(double(i) / n, double(j) / n);
          normal[i + (n + 1) * j] = dealii::cross_product_3d(x.x_u, x.x_v);
          area[i + (n + 1) * j]   = normal[i + (n + 1) * j].norm();
        }
      // Interior points first: a patch on a line has no normal anywhere, and
      // is better described so than by its first corner.
      for (const bool interior : {true, false})
        for (unsigned int j = 0; j <= n; ++j)
          for (unsigned int i = 0; i <= n; ++i)
            if ((i > 0 && i < n && j > 0 && j < n) == interior
                && !(area[i + (n + 1) * j] > tiny))
              return "x_u x x_v = 0 at " + at(i, j)
                     + (interior
                          ? ", so it has no normal there (its control points "
                            "lie on one line, or the net folds onto itself)"
                          : ", a collapsed edge or corner without a normal, "
                            "where a sheet node can be projected; split the "
                            "patch so that no edge or corner collapses");
      for (unsigned int j = 0; j <= n; ++j)
        for (unsigned int i = 0; i <= n; ++i)
        {
          const dealii::Tensor<1, 3> &c = normal[i + (n + 1) * j];
          const bool flips_u = i > 0 && c * normal[i - 1 + (n + 1) * j] < 0.;
          const bool flips_v = j > 0 && c * normal[i + (n + 1) * (j - 1)] < 0.;
          if (flips_u || flips_v)
            return "its normal x_u x x_v flips between " + at(i, j) + " and "
                   + (flips_u ? at(i - 1, j) : at(i, j - 1))
                   + ": the patch folds over onto itself";
        }
      return "";
    }
  } // namespace


  RigidTool
  read_tool_file(const std::string &filename)
  {
    // Regular, readable, at most 16 MB, text: a binary file is rejected
    // before any of its bytes is echoed (io/text_file.h).
    std::istringstream in(io::read_text_file(filename, "tool file"));

    unsigned int line_number = 0;
    const auto   fail        = [&](const std::string &message)
    {
      throw InputError(io::one_line(filename, 300) + ":"
                       + std::to_string(line_number) + ": "
                       + io::one_line(message, 500));
    };

    std::string                                               tool_name;
    bool                                                      has_name = false;
    std::vector<std::pair<BezierPatch, RigidTool::EdgeKinds>> patches;
    bool                                                      in_patch = false;
    PatchBlock                                                block;
    std::string                                               raw_line;
    while (std::getline(in, raw_line))
    {
      ++line_number;
      const std::string line   = trim(raw_line.substr(0, raw_line.find('#')));
      const auto        tokens = split(line);
      if (tokens.empty())
        continue;
      const std::string &keyword = tokens[0];

      if (!in_patch)
      {
        if (keyword == "tool")
        {
          if (has_name || !patches.empty())
            fail("'tool' must appear once, before the first patch");
          tool_name = trim(line.substr(4));
          if (tool_name.empty())
            fail("expected a tool name after 'tool'");
          has_name = true;
        }
        else if (keyword == "patch")
        {
          if (tokens.size() != 1)
            fail("expected nothing after 'patch', found \"" + line + "\"");
          in_patch         = true;
          block            = PatchBlock();
          block.first_line = line_number;
        }
        else
          fail("expected 'tool' or 'patch', found \"" + line + "\"");
        continue;
      }

      if (keyword == "tool" || keyword == "patch")
        fail("the patch started at line " + std::to_string(block.first_line)
             + " has no 'end' before this '" + keyword + "'");
      else if (keyword == "degrees")
      {
        if (block.has_degrees)
          fail("'degrees' given twice in one patch");
        if (tokens.size() != 3 || !parse_degree(tokens[1], block.p)
            || !parse_degree(tokens[2], block.q))
          fail("expected two degrees (integers), found \"" + line + "\"");
        if (block.p < 1 || block.q < 1)
          fail("degrees must be at least 1, found \"" + line + "\"");
        if (block.p > BezierPatch::max_degree
            || block.q > BezierPatch::max_degree)
          fail("degrees above the maximum "
               + std::to_string(BezierPatch::max_degree) + ", found \"" + line
               + "\"");
        block.has_degrees = true;
      }
      else if (keyword == "edges")
      {
        if (block.has_edges)
          fail("'edges' given twice in one patch");
        if (tokens.size() != 5 || !parse_edge_kind(tokens[1], block.edges[0])
            || !parse_edge_kind(tokens[2], block.edges[1])
            || !parse_edge_kind(tokens[3], block.edges[2])
            || !parse_edge_kind(tokens[4], block.edges[3]))
          fail("expected 'edges' and four of automatic, free, shared, symmetry "
               "(edges u=0 u=1 v=0 v=1), found \""
               + line + "\"");
        block.has_edges = true;
      }
      else if (keyword == "end")
      {
        if (tokens.size() != 1)
          fail("expected nothing after 'end', found \"" + line + "\"");
        if (!block.has_degrees)
          fail("the patch started at line " + std::to_string(block.first_line)
               + " has no 'degrees'");
        if (block.points.size() != block.n_expected())
          fail("degrees " + std::to_string(block.p) + " "
               + std::to_string(block.q) + " need "
               + std::to_string(block.n_expected()) + " control points ("
               + std::to_string(block.p + 1) + " x "
               + std::to_string(block.q + 1) + "), found "
               + std::to_string(block.points.size()));
        BezierPatch       patch(block.p, block.q, block.points, block.weights);
        const std::string degenerate = degenerate_patch(patch);
        if (!degenerate.empty())
          fail("the patch started at line " + std::to_string(block.first_line)
               + " is degenerate: " + degenerate);
        patches.emplace_back(std::move(patch), block.edges);
        in_patch = false;
      }
      else
      {
        // A control point: x y z w.
        std::array<double, 4> numbers;
        bool                  ok = tokens.size() == 4;
        for (unsigned int c = 0; ok && c < 4; ++c)
          ok = parse_double(tokens[c], numbers[c]);
        if (!ok)
          fail("expected 3 coordinates and a weight, found \"" + line + "\"");
        for (unsigned int c = 0; c < 4; ++c)
          if (!std::isfinite(numbers[c]))
            fail("expected finite numbers, found \"" + line + "\"");
        for (unsigned int c = 0; c < 3; ++c)
          if (!(std::abs(numbers[c]) <= max_coordinate))
            fail("coordinates must lie within +-1e6 mm, found \"" + line
                 + "\"");
        if (!(numbers[3] > 0.))
          fail("weights must be positive, found " + tokens[3] + " in \"" + line
               + "\"");
        if (!(numbers[3] >= min_weight && numbers[3] <= max_weight))
          fail("weights must lie between 1e-6 and 1e6, found " + tokens[3]
               + " in \"" + line + "\"");
        if (!block.has_degrees)
          fail("control point before the patch's 'degrees' line");
        if (block.points.size() == block.n_expected())
          fail("degrees " + std::to_string(block.p) + " "
               + std::to_string(block.q) + " need "
               + std::to_string(block.n_expected())
               + " control points; this is one more");
        block.points.emplace_back(numbers[0], numbers[1], numbers[2]);
        block.weights.push_back(numbers[3]);
      }
    }

    if (in_patch)
      fail("the patch started at line " + std::to_string(block.first_line)
           + " has no 'end'");
    if (patches.empty())
      fail("no patch in the tool file");

    if (!has_name)
      tool_name = std::filesystem::path(filename).stem().string();
    RigidTool tool(tool_name);
    for (const auto &[patch, edges] : patches)
      tool.add_patch(patch, edges);
    return tool;
  }


  void
  write_tool_file(const RigidTool &tool, const std::string &filename)
  {
    // Built in memory and written through a temporary file and a rename:
    // a failed write is an io::OutputError naming the file.
    std::ostringstream out;
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    out << "# deepdraw tool file (format: doc/tool_files.md)\n"
        << "# Each patch: 'degrees p q', then (p+1)(q+1) lines 'x y z weight' "
           "with\n"
        << "# the u index running fastest, then 'edges' (u=0 u=1 v=0 v=1), "
           "'end'.\n"
        << "# The normal x_u x x_v points towards the sheet.\n"
        << "tool " << tool.name() << "\n";
    for (unsigned int k = 0; k < tool.n_patches(); ++k)
    {
      const BezierPatch &patch = tool.patch(k);
      out << "\npatch # " << k << "\n"
          << "degrees " << patch.degree_u() << " " << patch.degree_v() << "\n";
      for (unsigned int n = 0; n < patch.control_points().size(); ++n)
      {
        const dealii::Point<3> &x = patch.control_points()[n];
        out << x[0] << " " << x[1] << " " << x[2] << " " << patch.weights()[n]
            << "\n";
      }
      const auto &edges = tool.declared_edge_kinds(k);
      out << "edges";
      for (const EdgeKind kind : edges)
        out << " " << to_string(kind);
      out << "\n# resolved:";
      for (unsigned int e = 0; e < 4; ++e)
        out << (tool.is_free_edge(k, e) ? " free" : " not-free");
      out << "\nend\n";
    }
    io::write_file_atomically(filename, out.str());
  }


  std::vector<std::string>
  write_tool_files(const std::vector<RigidTool> &tools,
                   const std::string            &directory)
  {
    std::filesystem::create_directories(directory);
    std::vector<std::string> filenames;
    for (const RigidTool &tool : tools)
    {
      std::string stem = tool.name();
      for (char &c : stem)
        if (c == ' ')
          c = '_';
      const std::string filename
        = (std::filesystem::path(directory) / (stem + ".tool")).string();
      write_tool_file(tool, filename);
      filenames.push_back(filename);
    }
    return filenames;
  }
} // namespace deepdraw::geometry
