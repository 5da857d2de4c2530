// Post-processor "forming limits" (doc/user_guide.md §8.2,
// doc/theory_formability.md §6, D140-D145, D172).
#include <algorithm>
#include <cmath>
#include <deepdraw/formability/flc_files.h>
#include <deepdraw/formability/forming_limit_curve_factory.h>
#include <deepdraw/io/binary_stream.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/postprocess/forming_limits.h>
#include <deepdraw/postprocess/profile_travels.h>
#include <deepdraw/postprocess/table_names.h>
#include <iomanip>
#include <sstream>

namespace deepdraw
{
  namespace postprocess
  {
    using formability::FldZone;

    namespace
    {
      const std::string state_name = "the forming limits' state";

      // classify()'s order of precedence: a column counts in the first of
      // these that one of its surfaces is in.
      constexpr std::array<FldZone, 6> zone_precedence
        = {{FldZone::split,
            FldZone::marginal,
            FldZone::thinning,
            FldZone::wrinkling_tendency,
            FldZone::insufficient_stretch,
            FldZone::safe}};

      // The columns of formability.csv after the worst point's, in the
      // order of the FldZone values.
      const std::vector<std::string> zone_columns = {"safe",
                                                     "marginal",
                                                     "split",
                                                     "thinning",
                                                     "insufficient_stretch",
                                                     "wrinkling_tendency"};

      // An Extreme value by value (no padding bytes in the checkpoint).
      void
      write_extreme(std::ostream &stream, const FormingLimits::Extreme &e)
      {
        io::write_value(stream, e.found);
        io::write_value(stream, e.surface);
        io::write_value(stream, e.point.zone);
        for (const double value : {e.load,
                                   e.centre[0],
                                   e.centre[1],
                                   e.point.major_strain,
                                   e.point.minor_strain,
                                   e.point.margin.strain,
                                   e.point.margin.percent})
          io::write_value(stream, value);
      }

      void
      read_extreme(std::istream &stream, FormingLimits::Extreme &e)
      {
        io::read_value(stream, e.found, state_name);
        io::read_value(stream, e.surface, state_name);
        io::read_value(stream, e.point.zone, state_name);
        for (double *value : {&e.load,
                              &e.centre[0],
                              &e.centre[1],
                              &e.point.major_strain,
                              &e.point.minor_strain,
                              &e.point.margin.strain,
                              &e.point.margin.percent})
          io::read_value(stream, *value, state_name);
      }

      // The least margin of a point and where it is.
      std::string
      least_margin_text(const FormingLimits::Extreme &point)
      {
        std::ostringstream text;
        text << std::setprecision(4) << "least margin "
             << point.point.margin.strain << ", " << point.point.margin.percent
             << " % of the limit, ";
        return text.str();
      }

      std::string
      place(const FormingLimits::Extreme &point)
      {
        std::ostringstream text;
        text << std::setprecision(6) << "at t = " << point.load
             << " mm at (X, Y) = (" << point.centre[0] << ", "
             << point.centre[1] << "), " << surface_name(point.surface)
             << " surface";
        return text.str();
      }
    } // namespace


    const std::string FormingLimits::name = "forming limits";


    void
    FormingLimits::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Formability");
      formability::FormabilityParameters::declare_parameters(prm);
      declare_travels(prm,
                      "FLD travels",
                      "15, 20",
                      "Loads (values of t; mm of punch travel in the "
                      "square cup) at which the post-processor 'forming "
                      "limits' writes the forming-limit diagram of every "
                      "column and surface (fld_<travel>mm.csv and .png); "
                      "increments land on them, travels beyond "
                      "Process/Final load are ignored. Travels must give "
                      "different file names (10 significant digits).");
      prm.leave_subsection();
    }


    void
    FormingLimits::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Formability");
      parameters.parse_parameters(prm, input_directory());
      travels = parse_travels(prm, "Formability/", "FLD travels", "fld_");
      prm.leave_subsection();
      if (parameters.curve_type
          == formability::FormabilityParameters::CurveType::none)
        throw InputError("Formability/Forming limit curve = none: the "
                         "post-processor '"
                         + name
                         + "' needs a forming-limit curve; allowed values "
                           "are tabulated, Keeler-Brazier, "
                           "Marciniak-Kuczynski");
    }


    void
    FormingLimits::initialize(const SimulationAccess &simulation)
    {
      if (!curve)
        curve = formability::create_forming_limit_curve(
          parameters,
          simulation.material().get_parameters(),
          simulation.blank().thickness);
      // After a refinement a column continues the path of the column its
      // cells came from (the same column on the same mesh).
      const ColumnStrains previous = std::move(column_strains);
      column_strains               = ColumnStrains();
      column_strains.set_up(simulation.sheet().triangulation(),
                            simulation.sheet().initial_vertices(),
                            simulation.thickness().sheet_thickness());
      const std::vector<unsigned int> parents
        = column_strains.inherited_from(previous);
      std::vector<formability::StrainPath> carried(3 * parents.size());
      for (unsigned int k = 0; k < parents.size(); ++k)
        if (parents[k] != numbers::invalid_unsigned_int)
          for (unsigned int s = 0; s < 3; ++s)
            carried[3 * k + s] = paths[3 * parents[k] + s];
      paths = std::move(carried);
    }


    std::vector<double>
    FormingLimits::requested_loads(const SimulationAccess &simulation) const
    {
      return travels_within(travels, simulation.final_load());
    }


    void
    FormingLimits::start(const SimulationAccess &simulation, const bool resume)
    {
      std::vector<std::string> columns = {tables::load,
                                          tables::worst_margin,
                                          "worst_margin_percent",
                                          "X",
                                          "Y",
                                          "surface",
                                          "eps1",
                                          "eps2",
                                          "thickness_strain",
                                          "path_ratio",
                                          "path_ratio_min",
                                          "path_ratio_max"};
      columns.insert(columns.end(), zone_columns.begin(), zone_columns.end());
      // The worst point beyond the curve's range (1) or within it (0), and
      // the least margin of the points within it (D172).
      columns.insert(columns.end(),
                     {tables::beyond_range, tables::in_range_margin});
      table.open(simulation.output_directory() + "/"
                   + tables::formability_table,
                 columns,
                 resume);
      // The curve beside the diagrams (fld_<travel>mm.gp plots flc.csv).
      formability::write_flc_files(*curve,
                                   parameters.zones,
                                   simulation.output_directory());
    }


    std::vector<FormingLimits::ColumnFld>
    FormingLimits::evaluate(const SimulationAccess &simulation) const
    {
      const std::vector<ColumnStrain> strains = column_strains.compute(
        simulation.sheet().triangulation().get_vertices(),
        simulation.thickness().sheet_thickness(),
        simulation.blank().thickness);
      std::vector<ColumnFld> result(strains.size());
      for (unsigned int k = 0; k < strains.size(); ++k)
      {
        result[k].thickness_strain = strains[k].thickness_strain;
        for (unsigned int s = 0; s < 3; ++s)
        {
          FldPoint &point    = result[k].surfaces[s];
          point.major_strain = strains[k].surfaces[s].major_strain;
          point.minor_strain = strains[k].surfaces[s].minor_strain;
          point.margin = curve->margin(point.major_strain, point.minor_strain);
          point.beyond_range = curve->beyond_range(point.minor_strain);
          point.zone         = formability::classify(curve.get(),
                                             parameters.zones,
                                             point.major_strain,
                                             point.minor_strain,
                                             strains[k].thickness_strain);
        }
      }
      return result;
    }


    const ColumnStrains &
    FormingLimits::columns() const
    {
      return column_strains;
    }


    FormingLimits::Extreme
    FormingLimits::worst_point(const std::vector<ColumnFld> &results,
                               const double                  load,
                               const bool within_range_only) const
    {
      Extreme worst;
      for (unsigned int k = 0; k < results.size(); ++k)
        for (const SheetSurface surface : sheet_surfaces)
        {
          const FldPoint &point = results[k].surfaces[unsigned(surface)];
          if (within_range_only && point.beyond_range)
            continue;
          if (!worst.found || point.margin.strain < worst.point.margin.strain)
            worst = {true, load, k, column_strains.centre(k), surface, point};
        }
      return worst;
    }


    std::array<unsigned int, 6>
    FormingLimits::zone_counts(const std::vector<ColumnFld> &results) const
    {
      std::array<unsigned int, 6> counts{};
      for (const ColumnFld &column : results)
        for (const FldZone zone : zone_precedence)
          if (std::any_of(column.surfaces.begin(),
                          column.surfaces.end(),
                          [&](const FldPoint &p) { return p.zone == zone; }))
          {
            ++counts[unsigned(zone)];
            break;
          }
      return counts;
    }


    void
    FormingLimits::execute(const SimulationAccess &simulation)
    {
      const double                 load    = simulation.state().load;
      const std::vector<ColumnFld> results = evaluate(simulation);
      for (unsigned int k = 0; k < results.size(); ++k)
        for (unsigned int s = 0; s < 3; ++s)
          paths[3 * k + s].add(results[k].surfaces[s].major_strain,
                               results[k].surfaces[s].minor_strain);

      const Extreme worst          = worst_point(results, load, false);
      const Extreme worst_in_range = worst_point(results, load, true);
      record(worst, first_crossing, least_margin);
      record(worst_in_range, first_crossing_in_range, least_margin_in_range);

      const unsigned int             column = worst.column;
      const formability::StrainPath &path
        = paths[3 * column + unsigned(worst.surface)];
      std::vector<double> row = {load,
                                 worst.point.margin.strain,
                                 worst.point.margin.percent,
                                 worst.centre[0],
                                 worst.centre[1],
                                 double(unsigned(worst.surface)),
                                 worst.point.major_strain,
                                 worst.point.minor_strain,
                                 results[column].thickness_strain,
                                 path.last_ratio(),
                                 path.least_ratio(),
                                 path.largest_ratio()};
      for (const unsigned int count : zone_counts(results))
        row.push_back(count);
      // No point within the range: 1e300, an infinite margin that a CSV
      // file holds and every reader parses (the largest double, printed to
      // 10 digits, would overflow).
      row.push_back(worst.point.beyond_range ? 1. : 0.);
      row.push_back(worst_in_range.found ? worst_in_range.point.margin.strain
                                         : 1e300);
      table.add_row(row);

      for (const double travel : requested_loads(simulation))
        if (std::abs(travel - load) < 1e-9 * std::max(1., travel))
          write_fld_files(simulation, results, travel);
    }


    void
    FormingLimits::write_fld_files(const SimulationAccess       &simulation,
                                   const std::vector<ColumnFld> &results,
                                   const double                  travel) const
    {
      std::vector<std::vector<double>> rows;
      for (unsigned int k = 0; k < results.size(); ++k)
        for (const SheetSurface surface : sheet_surfaces)
        {
          const FldPoint &point = results[k].surfaces[unsigned(surface)];
          rows.push_back({column_strains.centre(k)[0],
                          column_strains.centre(k)[1],
                          double(unsigned(surface)),
                          point.minor_strain,
                          point.major_strain,
                          point.margin.strain,
                          point.margin.percent,
                          double(unsigned(point.zone)),
                          point.beyond_range ? 1. : 0.});
        }
      const std::string stem      = "fld_" + travel_label(travel) + "mm";
      const std::string directory = simulation.output_directory();
      io::write_csv_file_atomically(directory + "/" + stem + ".csv",
                                    {"X",
                                     "Y",
                                     "surface",
                                     "eps2",
                                     "eps1",
                                     "margin",
                                     "margin_percent",
                                     "zone",
                                     tables::beyond_range},
                                    rows);
      formability::write_fld_plot(directory,
                                  stem,
                                  *curve,
                                  parameters.zones,
                                  "t = " + travel_label(travel) + " mm");
    }


    // The strain paths with their count (a resume rebuilds the same mesh,
    // D55), then the first crossing and the least margin, of all points and
    // of those within the curve's range.
    void
    FormingLimits::save(std::ostream &stream) const
    {
      io::write_value(stream, paths.size());
      for (const formability::StrainPath &path : paths)
        path.save(stream);
      for (const Extreme *extreme : {&first_crossing,
                                     &least_margin,
                                     &first_crossing_in_range,
                                     &least_margin_in_range})
        write_extreme(stream, *extreme);
    }


    void
    FormingLimits::load(std::istream &stream)
    {
      std::size_t n = 0;
      io::read_value(stream, n, state_name);
      if (n != paths.size())
        throw InputError("--resume: the checkpoint holds the strain paths "
                         "of "
                         + std::to_string(n / 3) + " columns, the mesh has "
                         + std::to_string(paths.size() / 3));
      for (formability::StrainPath &path : paths)
        path.load(stream, state_name);
      for (Extreme *extreme : {&first_crossing, &least_margin})
        read_extreme(stream, *extreme);
      if (stream.peek() != std::char_traits<char>::eof())
        for (Extreme *extreme :
             {&first_crossing_in_range, &least_margin_in_range})
          read_extreme(stream, *extreme);
      else
      {
        // A checkpoint written before D172 knows the points within the
        // range where the first crossing and the least margin are.
        first_crossing_in_range = least_margin_in_range = Extreme();
        for (auto [all, within] :
             {std::pair(&first_crossing, &first_crossing_in_range),
              std::pair(&least_margin, &least_margin_in_range)})
          if (all->found && curve
              && !curve->beyond_range(all->point.minor_strain))
            *within = *all;
      }
    }


    void
    FormingLimits::record(const Extreme &worst,
                          Extreme       &crossing,
                          Extreme       &least) const
    {
      if (!worst.found)
        return;
      if (!crossing.found && worst.point.margin.strain <= 0.)
        crossing = worst;
      if (!least.found || worst.point.margin.strain < least.point.margin.strain)
        least = worst;
    }


    std::string
    FormingLimits::summary() const
    {
      if (!least_margin.found)
        return "";
      const Extreme &extreme
        = first_crossing.found ? first_crossing : least_margin;
      std::string text
        = first_crossing.found
            ? "forming limit first crossed " + place(first_crossing)
            : "forming limit not crossed (" + least_margin_text(least_margin)
                + place(least_margin);
      if (curve->beyond_range(extreme.point.minor_strain))
      {
        // Not measured by the curve: say so, and what the points within its
        // range give (D172).
        const auto [low, high] = curve->minor_strain_range();
        std::ostringstream note;
        note << std::setprecision(4) << ", beyond the curve's range (eps2 = "
             << extreme.point.minor_strain << ", eps2/eps1 = "
             << extreme.point.minor_strain / extreme.point.major_strain
             << "; the curve is given for " << low << " <= eps2 <= " << high
             << " and only held at its end value beyond); within its range ";
        if (first_crossing_in_range.found)
          note << "first crossed " << place(first_crossing_in_range);
        else if (least_margin_in_range.found)
          note << "not crossed (" << least_margin_text(least_margin_in_range)
               << place(least_margin_in_range) << ")";
        else
          note << "no point";
        text += note.str();
      }
      return first_crossing.found ? text : text + ")";
    }

    DEEPDRAW_REGISTER_POSTPROCESSOR(
      FormingLimits,
      "forming limits",
      "formability.csv (the worst point of the sheet and the columns per "
      "zone at every increment), flc.csv/.png and fld_<travel>mm.csv/.png "
      "at Formability/FLD travels (the forming-limit diagram of every "
      "column's bottom, mid and top surface) against the curve of "
      "subsection Formability, and the first crossing of the curve at the "
      "end of the run; not in the default list.")
  } // namespace postprocess
} // namespace deepdraw
