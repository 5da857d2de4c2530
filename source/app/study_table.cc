// study.csv (doc/user_guide.md §4.2, doc/decisions.md D43).
#include <deepdraw/app/study_table.h>
#include <deepdraw/postprocess/table_names.h>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace deepdraw
{
  namespace app
  {
    namespace
    {
      // A text field, quoted (RFC 4180) if it holds a comma or a quote.
      std::string
      text_field(const std::string &text)
      {
        if (text.find_first_of(",\"\n") == std::string::npos)
          return text;
        std::string quoted = "\"";
        for (const char c : text)
          quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
        return quoted + "\"";
      }

      // Ten significant digits, as in every CSV file of deepdraw; empty if
      // the run did not give the value.
      std::string
      number_field(const OptionalValue &value)
      {
        if (!value)
          return "";
        std::ostringstream text;
        text << std::setprecision(10) << *value;
        return text.str();
      }
    } // namespace


    std::string
    StudyTable::at_travel(const std::string &quantity, const double travel)
    {
      return quantity + "_" + postprocess::travel_label(travel) + "mm";
    }


    StudyTable::StudyTable(const std::string              &name,
                           const std::vector<std::string> &variable_names,
                           const std::vector<double>      &travels,
                           const std::vector<std::string> &draw_in_names,
                           const bool                      formability)
        : filename(name)
        , formability(formability)
        , column_names(variable_names)
    {
      for (const char *column : {"status",
                                 "cells",
                                 "displacement_unknowns",
                                 "contact_unknowns",
                                 "aspect_ratio",
                                 "increments",
                                 "newton_iterations",
                                 "cut_backs",
                                 "wall_s"})
        column_names.emplace_back(column);
      std::vector<std::string> quantities = {postprocess::tables::punch_force};
      for (const std::string &point : draw_in_names)
        quantities.push_back(point + postprocess::tables::draw_in_suffix);
      for (const char *peak : {"OX_thinning",
                               "OX_thinning_s0_mm",
                               "OD_thinning",
                               "OD_thinning_s0_mm"})
        quantities.emplace_back(peak);
      for (const std::string &quantity : quantities)
        for (const double travel : travels)
          column_names.push_back(at_travel(quantity, travel));
      if (formability)
        for (const char *column : {"flc_first_crossing_mm",
                                   "flc_first_crossing_beyond_range",
                                   "flc_first_crossing_in_range_mm",
                                   "flc_least_margin",
                                   "flc_least_margin_in_range"})
          column_names.emplace_back(column);
      column_names.emplace_back("note");

      file.open(filename);
      std::string header;
      for (const std::string &column : column_names)
        header += (header.empty() ? "" : ",") + text_field(column);
      file << header << std::endl;
      if (!file)
        throw std::runtime_error("cannot write " + filename);
    }


    void
    StudyTable::add_row(const StudyRow &row)
    {
      std::vector<std::string> fields;
      for (const std::string &value : row.values)
        fields.push_back(text_field(value));
      const RunResults &r = row.results;
      fields.emplace_back(row.interrupted ? "interrupted"
                          : row.failed    ? "failed"
                                          : "ok");
      for (const OptionalValue &value : {r.cells,
                                         r.displacement_unknowns,
                                         r.contact_unknowns,
                                         row.aspect_ratio,
                                         r.increments,
                                         r.newton_iterations,
                                         r.cut_backs,
                                         OptionalValue(row.wall_seconds)})
        fields.push_back(number_field(value));

      // Quantity-major, as the header: each quantity at every travel.
      const std::size_t n_draw_in
        = r.travels.empty() ? 0 : r.travels.front().draw_in.size();
      const auto add = [&](const auto &get)
      {
        for (const TravelResults &at : r.travels)
          fields.push_back(number_field(get(at)));
      };
      add([](const TravelResults &at) { return at.punch_force; });
      for (std::size_t p = 0; p < n_draw_in; ++p)
        add([p](const TravelResults &at) { return at.draw_in[p]; });
      add([](const TravelResults &at) { return at.ox_strain; });
      add([](const TravelResults &at) { return at.ox_s0; });
      add([](const TravelResults &at) { return at.od_strain; });
      add([](const TravelResults &at) { return at.od_s0; });
      if (formability)
        for (const OptionalValue &value : {r.flc_first_crossing,
                                           r.flc_first_crossing_beyond_range,
                                           r.flc_first_crossing_in_range,
                                           r.flc_least_margin,
                                           r.flc_least_margin_in_range})
          fields.push_back(number_field(value));
      fields.push_back(text_field(row.note));

      if (fields.size() != column_names.size())
        throw std::logic_error("wrong number of fields for " + filename);
      std::string line;
      for (const std::string &field : fields)
        line += (line.empty() ? "" : ",") + field;
      file << line << std::endl;
      if (!file)
        throw std::runtime_error("cannot write " + filename);
    }


    const std::vector<std::string> &
    StudyTable::columns() const
    {
      return column_names;
    }
  } // namespace app
} // namespace deepdraw
