// flc.csv, flc.gp and flc.png (doc/user_guide.md §8).
#include <cmath>
#include <deepdraw/formability/flc_files.h>
#include <deepdraw/formability/forming_limit_curve_factory.h>
#include <deepdraw/io/csv_file.h>
#include <deepdraw/io/gnuplot.h>
#include <deepdraw/io/output_file.h>
#include <sstream>

namespace deepdraw
{
  namespace formability
  {
    namespace
    {
      // The lines every picture of the curve begins with: png (a PNG of
      // 800 x 600 pixels) and its title, from CSV files with a header.
      std::string
      plot_header(const std::string &script,
                  const std::string &png,
                  const std::string &title)
      {
        return "# Written by deepdraw (doc/user_guide.md §8); run 'gnuplot "
               + script
               + "' here.\n"
                 "set terminal png size 800,600 font 'DejaVuSans,10' "
                 "noenhanced\n"
                 "set output '"
               + png
               + "'\n"
                 "set datafile separator ','\n"
                 "set datafile columnheaders\n"
                 "set grid\n"
                 "set title "
               + io::gnuplot_string(title)
               + "\n"
                 "set xlabel 'minor strain eps2 (true)'\n"
                 "set ylabel 'major strain eps1 (true)'\n";
      }

      // The plot clauses of flc.csv: the curve as `style`, and its safety
      // band (dashed) if there is one.
      std::string
      curve_clauses(const std::string &style, const double safety_band)
      {
        std::string clauses
          = "'flc.csv' using 1:2 with " + style + " title 'FLC'";
        if (safety_band > 0.)
        {
          std::ostringstream band;
          band << safety_band;
          clauses += ", \\\n     'flc.csv' using 1:((1 - " + band.str()
                     + " / 100.) * $2) with lines dashtype 2 lc rgb '#555555' "
                       "title "
                     + io::gnuplot_string("safety band (" + band.str()
                                          + " % of the limit)");
        }
        return clauses;
      }

      std::string
      script(const FormingLimitCurve &curve, const double safety_band)
      {
        return plot_header("flc.gp",
                           "flc.png",
                           "Forming-limit curve: " + curve.description())
               + "set key top center\nset yrange [0:*]\nplot "
               + curve_clauses("linespoints lw 2 pt 7 ps 0.7", safety_band)
               + "\n";
      }

      // The zones in the order of their values (FldZone) with a colour
      // each: green safe, orange marginal, red split, purple thinning,
      // grey insufficient stretch, blue wrinkling tendency.
      const std::pair<FldZone, const char *> zone_colours[]
        = {{FldZone::safe, "#1a9850"},
           {FldZone::marginal, "#fd8d3c"},
           {FldZone::split, "#d7191c"},
           {FldZone::thinning, "#7b3294"},
           {FldZone::insufficient_stretch, "#969696"},
           {FldZone::wrinkling_tendency, "#2c7bb6"}};
    } // namespace


    std::string
    write_flc_files(const FormingLimitCurve &curve,
                    const FldZoneParameters &zones,
                    const std::string       &directory)
    {
      const std::vector<FlcPoint> points = curve.points();
      bool                        mk     = false;
      for (const FlcPoint &point : points)
        mk = mk || std::isfinite(point.groove_angle);
      std::vector<std::string> columns = {"eps2", "eps1"};
      if (mk)
        columns.insert(columns.end(), {"strain_ratio", "groove_angle_deg"});
      std::vector<std::vector<double>> rows;
      for (const FlcPoint &point : points)
      {
        rows.push_back({point.minor_strain, point.major_strain});
        if (mk)
          rows.back().insert(rows.back().end(),
                             {point.strain_ratio, point.groove_angle});
      }
      io::write_csv_file_atomically(directory + "/flc.csv", columns, rows);
      return io::plot_with_gnuplot(directory,
                                   "flc",
                                   script(curve, zones.safety_band));
    }


    std::string
    write_flc_files(const FormabilityParameters        &parameters,
                    const material::MaterialParameters &material,
                    const double                        sheet_thickness,
                    const std::string                  &directory)
    {
      return write_flc_files(
        *create_required_forming_limit_curve(parameters,
                                             material,
                                             sheet_thickness),
        parameters.zones,
        directory);
    }


    std::string
    write_fld_plot(const std::string       &directory,
                   const std::string       &stem,
                   const FormingLimitCurve &curve,
                   const FldZoneParameters &zones,
                   const std::string       &when)
    {
      // Columns of the diagram: eps2 4, eps1 5, zone 8; a point of another
      // zone is left out of a clause (1/0).
      std::ostringstream gp;
      gp << plot_header(stem + ".gp",
                        stem + ".png",
                        "Forming-limit diagram at " + when + ": "
                          + curve.description())
         << "set key below\nplot "
         << curve_clauses("lines lw 2 lc rgb 'black'", zones.safety_band);
      for (const auto &[zone, colour] : zone_colours)
        gp << ", \\\n     '" << stem
           << ".csv' using 4:($8 == " << unsigned(zone)
           << " ? $5 : 1/0) with points pt 7 ps 0.5 lc rgb '" << colour
           << "' title " << io::gnuplot_string(zone_name(zone));
      gp << "\n";
      return io::plot_with_gnuplot(directory, stem, gp.str());
    }
  } // namespace formability
} // namespace deepdraw
