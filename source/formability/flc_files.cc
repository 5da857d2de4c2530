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
      std::string
      script(const FormingLimitCurve &curve, const double safety_band)
      {
        std::ostringstream gp;
        gp << "# Written by deepdraw (doc/user_guide.md §8); run 'gnuplot "
              "flc.gp' here.\n"
           << "set terminal png size 800,600 font 'DejaVuSans,10' "
              "noenhanced\n"
           << "set output 'flc.png'\n"
           << "set datafile separator ','\n"
           << "set datafile columnheaders\n"
           << "set grid\nset key top center\n"
           << "set title "
           << io::gnuplot_string("Forming-limit curve: " + curve.description())
           << "\n"
           << "set xlabel 'minor strain eps2 (true)'\n"
           << "set ylabel 'major strain eps1 (true)'\n"
           << "set yrange [0:*]\n"
           << "plot 'flc.csv' using 1:2 with linespoints lw 2 pt 7 ps 0.7 "
              "title 'FLC'";
        if (safety_band > 0.)
        {
          std::ostringstream band;
          band << safety_band;
          gp << ", \\\n     'flc.csv' using 1:((1 - " << band.str()
             << " / 100.) * $2) with lines dashtype 2 title "
             << io::gnuplot_string("safety band (" + band.str()
                                   + " % of the limit)");
        }
        gp << "\n";
        return gp.str();
      }
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
      io::write_file_atomically(directory + "/flc.gp",
                                script(curve, zones.safety_band));
      return io::run_gnuplot(directory, "flc.gp", "flc.png");
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
  } // namespace formability
} // namespace deepdraw
