#include <algorithm>
#include <deal.II/base/utilities.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/postprocess/profile_travels.h>
#include <deepdraw/postprocess/table_names.h>
#include <iomanip>
#include <map>
#include <sstream>

namespace deepdraw
{
  namespace postprocess
  {
    using namespace dealii;

    std::string
    travel_label(const double travel)
    {
      std::ostringstream label;
      label << std::setprecision(10) << travel;
      return label.str();
    }


    std::string
    thickness_profile_file(const std::string &profile, const double travel)
    {
      return "thickness_" + profile + "_" + travel_label(travel) + "mm.csv";
    }


    void
    declare_travels(ParameterHandler  &prm,
                    const std::string &entry,
                    const std::string &default_value,
                    const std::string &documentation)
    {
      prm.declare_entry(entry,
                        default_value,
                        Patterns::List(Patterns::Double(0., 1e6)),
                        documentation);
    }


    std::vector<double>
    parse_travels(ParameterHandler  &prm,
                  const std::string &section,
                  const std::string &entry,
                  const std::string &file_prefix)
    {
      std::vector<double> travels;
      for (const std::string &travel :
           Utilities::split_string_list(prm.get(entry)))
        travels.push_back(Utilities::string_to_double(travel));

      // Equal travels are one file; different travels with the same
      // label would write one file twice (D51).
      std::map<std::string, double> labels;
      for (const double travel : travels)
      {
        const auto [it, added] = labels.emplace(travel_label(travel), travel);
        if (!added && it->second != travel)
        {
          std::ostringstream text;
          text << std::setprecision(17) << section << entry << ": "
               << it->second << " and " << travel << " both give the file name "
               << file_prefix << it->first
               << "mm.csv; travels must differ in their first "
                  "10 significant digits";
          throw InputError(text.str());
        }
      }
      return travels;
    }


    void
    declare_profile_travels(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      declare_travels(prm,
                      "Thickness profile travels",
                      "15, 20",
                      "Final loads (values of t, mm) at which the "
                      "thickness strain along OX, OY and OD and the "
                      "earing profile are written "
                      "(thickness_OX_<travel>mm.csv, ..., "
                      "earing_<travel>mm.csv; runs with tools "
                      "only); increments land on them, travels beyond "
                      "Process/Final load are ignored. Travels must give "
                      "different file names (10 significant digits).");
      prm.leave_subsection();
    }


    std::vector<double>
    parse_profile_travels(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      const std::vector<double> travels
        = parse_travels(prm,
                        "Output/",
                        "Thickness profile travels",
                        "thickness_OX_");
      prm.leave_subsection();
      return travels;
    }


    std::vector<double>
    travels_within(const std::vector<double> &travels, const double final_load)
    {
      std::vector<double> within;
      for (const double travel : travels)
        if (travel <= final_load * (1. + 1e-12))
          within.push_back(travel);
      std::sort(within.begin(), within.end());
      within.erase(std::unique(within.begin(), within.end()), within.end());
      return within;
    }
  } // namespace postprocess
} // namespace deepdraw
