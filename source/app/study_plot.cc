// study.png through gnuplot (doc/decisions.md D43).
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deepdraw/app/study_plot.h>
#include <deepdraw/app/study_table.h>
#include <deepdraw/io/gnuplot.h>
#include <deepdraw/postprocess/table_names.h>
#include <fstream>
#include <sstream>

namespace deepdraw
{
  namespace app
  {
    namespace
    {
      struct Curve
      {
        std::string column;
        std::string title;
      };

      struct Panel
      {
        std::string        title;
        std::vector<Curve> curves;
      };

      std::vector<Panel>
      panels_of(const StudyPlotSpec &spec)
      {
        std::vector<Panel> panels
          = {{"cells", {{"cells", ""}}},
             {"unknowns",
              {{"displacement_unknowns", "displacement"},
               {"contact_unknowns", "contact"}}},
             {"aspect ratio (in-plane size / layer)", {{"aspect_ratio", ""}}},
             {"increments", {{"increments", ""}}},
             {"Newton iterations", {{"newton_iterations", ""}}},
             {"cut-backs", {{"cut_backs", ""}}},
             {"wall time (s)", {{"wall_s", ""}}}};
        std::vector<std::pair<std::string, std::string>> quantities
          = {{postprocess::tables::punch_force, "punch force (N)"}};
        for (const std::string &point : spec.draw_in_names)
          quantities.emplace_back(point + postprocess::tables::draw_in_suffix,
                                  point + " draw-in (mm)");
        quantities.insert(quantities.end(),
                          {{"OX_thinning", "OX: smallest ln(t/t0)"},
                           {"OX_thinning_s0_mm", "OX: its s0 (mm)"},
                           {"OD_thinning", "OD: smallest ln(t/t0)"},
                           {"OD_thinning_s0_mm", "OD: its s0 (mm)"}});
        // A panel per travel: the values at different travels differ by
        // more than a refinement changes them.
        for (const auto &[quantity, title] : quantities)
          for (const double travel : spec.travels)
            panels.push_back(
              {title + " at " + postprocess::travel_label(travel) + " mm",
               {{StudyTable::at_travel(quantity, travel), ""}}});
        return panels;
      }

      // 1-based column index of name in spec.columns, 0 if absent.
      unsigned int
      column_number(const StudyPlotSpec &spec, const std::string &name)
      {
        for (unsigned int c = 0; c < spec.columns.size(); ++c)
          if (spec.columns[c] == name)
            return c + 1;
        return 0;
      }


      std::string
      script(const StudyPlotSpec &spec)
      {
        const std::vector<Panel> panels = panels_of(spec);
        const unsigned int       n_columns
          = std::ceil(std::sqrt(double(panels.size())));
        const unsigned int n_rows = (panels.size() + n_columns - 1) / n_columns;
        const unsigned int x      = column_number(spec, spec.x_column);
        const unsigned int status = column_number(spec, "status");

        std::ostringstream gp;
        gp << "# Written by deepdraw --study (doc/user_guide.md §4.2); run "
              "'gnuplot study.gp' here.\n"
           // libgd's png: a palette image, a quarter of pngcairo's size.
           << "set terminal png size " << 280 * n_columns << ","
           << 200 * n_rows + 30 << " font 'DejaVuSans,7' noenhanced\n"
           << "set output 'study.png'\n"
           << "set datafile separator ','\n"
           << "set datafile columnheaders\n"
           // Failed runs are NaN in the plot, and their neighbours joined.
           << "set datafile missing NaN\n"
           << "set offsets graph 0.05, graph 0.05, graph 0.1, graph 0.1\n"
           << "set grid\nset key top left\n"
           << "set xlabel " << io::gnuplot_string(spec.x_label) << "\n"
           << "ok_value(c) = strcol(" << status
           << ") eq 'ok' ? column(c) : NaN\n"
           << "set multiplot layout " << n_rows << "," << n_columns << " title "
           << io::gnuplot_string(spec.title) << "\n";
        const std::string x_using = spec.x_numeric ? std::to_string(x) : "0";
        const std::string labels
          = spec.x_numeric ? "" : ":xticlabels(" + std::to_string(x) + ")";
        for (const Panel &panel : panels)
        {
          gp << "set title " << io::gnuplot_string(panel.title) << "\nplot ";
          for (unsigned int k = 0; k < panel.curves.size(); ++k)
            gp << (k ? ", \\\n     " : "") << "'study.csv' using " << x_using
               << ":(ok_value(" << column_number(spec, panel.curves[k].column)
               << "))" << labels << " with linespoints pt 7 ps 0.6 title "
               << io::gnuplot_string(panel.curves[k].title);
          gp << "\n";
        }
        gp << "unset multiplot\n";
        return gp.str();
      }
    } // namespace


    std::string
    plot_study(const std::string &directory, const StudyPlotSpec &spec)
    {
      return io::plot_with_gnuplot(directory, "study", script(spec));
    }
  } // namespace app
} // namespace deepdraw
