#include <algorithm>
#include <cmath>
#include <deepdraw/io/csv_file.h>
#include <deepdraw/io/output_file.h>
#include <deepdraw/postprocess/earing_profile.h>
#include <limits>
#include <map>
#include <sstream>

namespace deepdraw
{
  namespace postprocess
  {
    void
    EaringProfile::set_up(const Triangulation<3>      &triangulation,
                          const std::vector<Point<3>> &initial_vertices,
                          const std::vector<types::boundary_id> &rim_ids,
                          const double rolling_direction_angle)
    {
      double extent = 0.;
      for (const Point<3> &X : initial_vertices)
        extent = std::max(extent, std::hypot(X[0], X[1]));
      // Vertices of one column share (X, Y) to round-off.
      const double grid = 1e-7 * std::max(extent, 1.);
      std::map<std::pair<long long, long long>, std::vector<unsigned int>>
                        columns;
      std::vector<bool> seen(initial_vertices.size(), false);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary()
              && std::find(rim_ids.begin(), rim_ids.end(), face->boundary_id())
                   != rim_ids.end())
            for (const unsigned int v : face->vertex_indices())
            {
              const unsigned int vertex = face->vertex_index(v);
              if (seen[vertex])
                continue;
              seen[vertex]      = true;
              const Point<3> &X = initial_vertices[vertex];
              columns[{std::llround(X[0] / grid), std::llround(X[1] / grid)}]
                .push_back(vertex);
            }
      rim.clear();
      for (const auto &[key, vertices] : columns)
      {
        const Point<3> &X = initial_vertices[vertices.front()];
        double          angle
          = std::atan2(X[1], X[0]) * 180. / M_PI - rolling_direction_angle;
        // In (-180, 180].
        angle = angle - 360. * std::ceil((angle - 180.) / 360.);
        rim.push_back({angle, vertices});
      }
      std::sort(rim.begin(),
                rim.end(),
                [](const RimColumn &a, const RimColumn &b)
                { return a.angle_deg < b.angle_deg; });
    }


    std::vector<std::pair<double, double>>
    EaringProfile::heights(const std::vector<Point<3>> &vertices,
                           const Tensor<1, 3>          &punch_direction) const
    {
      // Heights against the punch motion, from the outside of the cup
      // bottom (the lowest point of the sheet).
      double bottom = std::numeric_limits<double>::max();
      for (const Point<3> &x : vertices)
        bottom = std::min(bottom, -(punch_direction * x));
      std::vector<std::pair<double, double>> rows;
      for (const RimColumn &column : rim)
      {
        double top = -std::numeric_limits<double>::max();
        for (const unsigned int v : column.vertices)
          top = std::max(top, -(punch_direction * vertices[v]));
        rows.emplace_back(column.angle_deg, top - bottom);
      }
      return rows;
    }


    void
    EaringProfile::write(const std::string           &directory,
                         const std::string           &label,
                         const std::vector<Point<3>> &vertices,
                         const Tensor<1, 3>          &punch_direction) const
    {
      std::vector<std::vector<double>> rows;
      for (const auto &[angle, height] : heights(vertices, punch_direction))
        rows.push_back({angle, height});
      io::write_csv_file_atomically(directory + "/earing_" + label + "mm.csv",
                                    {"angle_deg", "height_mm"},
                                    rows);
    }


    void
    EaringProfile::write_plot_script(const std::string              &directory,
                                     const std::vector<std::string> &labels)
    {
      std::ostringstream gp;
      gp << "# Written by deepdraw (doc/user_guide.md §3.1): run 'gnuplot "
            "earing.gp' here for earing.png.\n"
         << "set terminal png size 640,420 font 'DejaVuSans,9' noenhanced\n"
         << "set output 'earing.png'\n"
         << "set datafile separator ','\n"
         << "set datafile columnheaders\n"
         << "set grid\nset key bottom right\n"
         << "set xlabel 'angle from the rolling direction (deg)'\n"
         << "set ylabel 'cup height (mm)'\n"
         << "set xtics 15\n"
         << "plot ";
      for (unsigned int k = 0; k < labels.size(); ++k)
        gp << (k ? ", \\\n     " : "") << "'earing_" << labels[k]
           << "mm.csv' using 1:2 with linespoints pt 7 ps 0.5 title 'travel "
           << labels[k] << " mm'";
      gp << "\n";
      io::write_file_atomically(directory + "/earing.gp", gp.str());
    }
  } // namespace postprocess
} // namespace deepdraw
