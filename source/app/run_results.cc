// Reading one run's outputs back (doc/user_guide.md §3, doc/decisions.md
// D42).
#include <cmath>
#include <deepdraw/app/run_results.h>
#include <deepdraw/postprocess/table_names.h>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>

namespace deepdraw
{
  namespace app
  {
    namespace
    {
      // A CSV file of deepdraw (io::CsvFile): a header, then numbers.
      struct Table
      {
        std::vector<std::string>         columns;
        std::vector<std::vector<double>> rows;

        // The column's index, or -1.
        int
        column(const std::string &name) const
        {
          for (unsigned int c = 0; c < columns.size(); ++c)
            if (columns[c] == name)
              return c;
          return -1;
        }
      };

      std::vector<std::string>
      split_commas(const std::string &line)
      {
        std::vector<std::string> cells;
        std::stringstream        stream(line);
        std::string              cell;
        while (std::getline(stream, cell, ','))
          cells.push_back(cell);
        return cells;
      }

      // Empty if the file does not exist; a row that is not all numbers
      // (a run killed while writing it) ends the table.
      std::optional<Table>
      read_table(const std::string &filename)
      {
        std::ifstream file(filename);
        std::string   line;
        if (!file || !std::getline(file, line))
          return std::nullopt;
        Table table;
        table.columns = split_commas(line);
        while (std::getline(file, line))
        {
          std::vector<double> row;
          try
          {
            for (const std::string &cell : split_commas(line))
              row.push_back(std::stod(cell));
          }
          catch (const std::exception &)
          {
            break;
          }
          if (row.size() != table.columns.size())
            break;
          table.rows.push_back(row);
        }
        return table;
      }


      bool
      same_travel(const double a, const double b)
      {
        return std::abs(a - b) <= 1e-9 * std::max(1., std::abs(b));
      }


      // Value of column `name` in the row whose first column is the travel.
      OptionalValue
      value_at(const std::optional<Table> &table,
               const std::string          &name,
               const double                travel)
      {
        if (!table)
          return std::nullopt;
        const int c = table->column(name);
        if (c < 0)
          return std::nullopt;
        for (const std::vector<double> &row : table->rows)
          if (same_travel(row[0], travel))
            return row[c];
        return std::nullopt;
      }


      // The smallest thickness strain of a profile file and its s0.
      void
      read_peak(const std::string &filename,
                OptionalValue     &strain,
                OptionalValue     &s0)
      {
        const std::optional<Table> table = read_table(filename);
        if (!table)
          return;
        const int c_s0 = table->column(postprocess::tables::profile_distance);
        const int c_e  = table->column(postprocess::tables::thickness_strain);
        if (c_s0 < 0 || c_e < 0)
          return;
        for (const std::vector<double> &row : table->rows)
          if (!strain || row[c_e] < *strain)
          {
            strain = row[c_e];
            s0     = row[c_s0];
          }
      }


      void
      read_mesh_size(const std::string &log_file, RunResults &results)
      {
        std::ifstream    file(log_file);
        std::string      line;
        const std::regex pattern("^deepdraw: ([0-9]+) cells, ([0-9]+) "
                                 "displacement unknowns, ([0-9]+) contact "
                                 "unknowns");
        std::smatch      match;
        while (std::getline(file, line))
          if (std::regex_search(line, match, pattern))
          {
            results.cells                 = std::stod(match[1]);
            results.displacement_unknowns = std::stod(match[2]);
            results.contact_unknowns      = std::stod(match[3]);
            return;
          }
      }


      void
      read_cost(const std::string &statistics_file, RunResults &results)
      {
        const std::optional<Table> table = read_table(statistics_file);
        if (!table)
          return;
        results.increments = table->rows.size();
        const std::pair<const char *, OptionalValue *> sums[]
          = {{postprocess::tables::newton_iterations.c_str(),
              &results.newton_iterations},
             {postprocess::tables::cut_backs.c_str(), &results.cut_backs}};
        for (const auto &[name, sum] : sums)
        {
          const int c = table->column(name);
          if (c < 0)
            continue;
          *sum = 0.;
          for (const std::vector<double> &row : table->rows)
            **sum += row[c];
        }
      }


      // The first crossing of the forming-limit curve and the least margin
      // (D174).
      void
      read_formability(const std::string &filename, RunResults &results)
      {
        namespace tables                 = postprocess::tables;
        const std::optional<Table> table = read_table(filename);
        if (!table)
          return;
        const int load     = table->column(tables::load);
        const int margin   = table->column(tables::worst_margin);
        const int beyond   = table->column(tables::beyond_range);
        const int in_range = table->column(tables::in_range_margin);
        if (load < 0 || margin < 0 || beyond < 0 || in_range < 0)
          return;
        const auto least = [](OptionalValue &value, const double x)
        {
          if (!value || x < *value)
            value = x;
        };
        for (const std::vector<double> &row : table->rows)
        {
          if (!results.flc_first_crossing && row[margin] <= 0.)
          {
            results.flc_first_crossing              = row[load];
            results.flc_first_crossing_beyond_range = row[beyond];
          }
          if (!results.flc_first_crossing_in_range && row[in_range] <= 0.)
            results.flc_first_crossing_in_range = row[load];
          least(results.flc_least_margin, row[margin]);
          least(results.flc_least_margin_in_range, row[in_range]);
        }
      }
    } // namespace


    RunResults
    read_run_results(const std::string              &directory,
                     const std::vector<double>      &travels,
                     const std::vector<std::string> &draw_in_names)
    {
      RunResults results;
      read_mesh_size(directory + "/deepdraw.log", results);
      read_cost(directory + "/" + postprocess::tables::statistics, results);

      const std::optional<Table> punch
        = read_table(directory + "/" + postprocess::tables::punch_force_table);
      const std::optional<Table> draw_in
        = read_table(directory + "/" + postprocess::tables::draw_in_table);
      for (const double travel : travels)
      {
        TravelResults at;
        at.punch_force
          = value_at(punch, postprocess::tables::punch_force, travel);
        for (const std::string &name : draw_in_names)
          at.draw_in.push_back(
            value_at(draw_in,
                     name + postprocess::tables::draw_in_suffix,
                     travel));
        read_peak(directory + "/"
                    + postprocess::thickness_profile_file("OX", travel),
                  at.ox_strain,
                  at.ox_s0);
        read_peak(directory + "/"
                    + postprocess::thickness_profile_file("OD", travel),
                  at.od_strain,
                  at.od_s0);
        results.travels.push_back(at);
      }
      read_formability(directory + "/" + postprocess::tables::formability_table,
                       results);
      return results;
    }
  } // namespace app
} // namespace deepdraw
