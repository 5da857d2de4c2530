#include <array>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deepdraw/geometry/tool_vtu.h>
#include <deepdraw/io/output_error.h>
#include <deepdraw/io/output_file.h>
#include <sstream>

namespace deepdraw::geometry
{
  namespace
  {
    // The tool name inside an XML comment: "--" and markup would end or
    // break it, so that ParaView could not read the file.
    std::string
    comment_text(std::string name)
    {
      for (char &c : name)
        if (c == '-' || c == '<' || c == '>' || c == '&'
            || static_cast<unsigned char>(c) < 0x20)
          c = '_';
      return name;
    }
  } // namespace


  void
  write_vtu(const RigidTool   &tool,
            const std::string &filename,
            const unsigned int subdivisions)
  {
    AssertThrow(subdivisions >= 1,
                dealii::ExcMessage("write_vtu: subdivisions must be >= 1"));
    // Built in memory, checked, then written through a temporary file and
    // a rename (io::write_file_atomically): a failed write is an
    // io::OutputError naming the file, and a partial file never stays.
    std::ostringstream out;
    out.precision(10);

    const unsigned int n_side   = subdivisions + 1;
    const unsigned int n_points = tool.n_patches() * n_side * n_side;
    const auto        &rotation = tool.rotation();

    // Two triangles per grid square; on a trimmed patch only the squares
    // whose centre lies inside the face's loops (doc/tool_files.md, CAD
    // tools).
    std::vector<std::array<unsigned int, 3>> triangles;
    std::vector<unsigned int>                triangle_patch;
    for (unsigned int k = 0; k < tool.n_patches(); ++k)
      for (unsigned int j = 0; j < subdivisions; ++j)
        for (unsigned int i = 0; i < subdivisions; ++i)
        {
          const PatchTrimming &trimming = tool.trimming(k);
          if (trimming.trimmed())
          {
            const double       s     = (i + 0.5) / subdivisions;
            const double       t     = (j + 0.5) / subdivisions;
            const SurfacePoint point = tool.patch(k).derivatives(s, t);
            if (!trimming.contains(s, t, point.x_u, point.x_v))
              continue;
          }
          const unsigned int v00 = k * n_side * n_side + j * n_side + i;
          const unsigned int v10 = v00 + 1, v01 = v00 + n_side, v11 = v01 + 1;
          triangles.push_back({{v00, v10, v11}});
          triangles.push_back({{v00, v11, v01}});
          triangle_patch.insert(triangle_patch.end(), 2, k);
        }
    const unsigned int n_cells = triangles.size();

    out << "<?xml version=\"1.0\"?>\n"
        << "<!-- tool '" << comment_text(tool.name()) << "', "
        << tool.n_patches() << " Bezier patches -->\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n"
        << "<UnstructuredGrid>\n"
        << "<Piece NumberOfPoints=\"" << n_points << "\" NumberOfCells=\""
        << n_cells << "\">\n"
        << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
           "format=\"ascii\">\n";
    for (const BezierPatch &patch : tool.patches())
      for (unsigned int j = 0; j < n_side; ++j)
        for (unsigned int i = 0; i < n_side; ++i)
        {
          const dealii::Point<3> x = tool.to_global(
            patch.value(i / double(subdivisions), j / double(subdivisions)));
          for (unsigned int d = 0; d < 3; ++d)
            if (!std::isfinite(x[d]))
              throw io::OutputError("a non-finite point of tool '" + tool.name()
                                    + "' in " + filename
                                    + "; deepdraw writes no NaN or inf");
          out << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
        }
    out
      << "</DataArray>\n</Points>\n<Cells>\n"
      << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto &triangle : triangles)
      out << triangle[0] << ' ' << triangle[1] << ' ' << triangle[2] << '\n';
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
           "format=\"ascii\">\n";
    for (unsigned int c = 1; c <= n_cells; ++c)
      out << 3 * c << '\n';
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
           "format=\"ascii\">\n";
    for (unsigned int c = 0; c < n_cells; ++c)
      out << "5\n"; // VTK_TRIANGLE
    out << "</DataArray>\n</Cells>\n<PointData Normals=\"normal\">\n"
        << "<DataArray type=\"Float64\" Name=\"normal\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const BezierPatch &patch : tool.patches())
      for (unsigned int j = 0; j < n_side; ++j)
        for (unsigned int i = 0; i < n_side; ++i)
        {
          dealii::Tensor<1, 3> n
            = rotation
              * patch.unit_normal(i / double(subdivisions),
                                  j / double(subdivisions));
          // A collapsed edge has no normal.
          if (!(std::isfinite(n[0]) && std::isfinite(n[1])
                && std::isfinite(n[2])))
            n = 0;
          out << n[0] << ' ' << n[1] << ' ' << n[2] << '\n';
        }
    out << "</DataArray>\n</PointData>\n<CellData Scalars=\"patch\">\n"
        << "<DataArray type=\"Int32\" Name=\"patch\" format=\"ascii\">\n";
    for (const unsigned int k : triangle_patch)
      out << k << '\n';
    out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</"
           "VTKFile>\n";
    io::write_file_atomically(filename, out.str());
  }
} // namespace deepdraw::geometry
