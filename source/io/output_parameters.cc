#include <algorithm>
#include <deal.II/base/utilities.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/output_parameters.h>
#include <iomanip>
#include <map>
#include <sstream>

namespace deepdraw
{
  namespace io
  {
    void
    OutputParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Output directory",
                        "output",
                        Patterns::DirectoryName(),
                        "Directory for all results (created if missing; the "
                        "command-line option --output-directory overrides "
                        "it).");
      prm.declare_entry("Output interval",
                        "0",
                        Patterns::Double(0., 1e6),
                        "Load-parameter interval between VTU outputs "
                        "(increments land on these loads); 0 writes every "
                        "converged increment. At most 100000 outputs "
                        "(Final load / Output interval).");
      prm.declare_entry("Write VTU",
                        "true",
                        Patterns::Bool(),
                        "Write the VTU/PVD files for ParaView (the CSV "
                        "tables are always written).");
      prm.declare_entry("Thickness profile travels",
                        "15, 20",
                        Patterns::List(Patterns::Double(0., 1e6)),
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


    void
    OutputParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      output_directory = prm.get("Output directory");
      output_interval  = prm.get_double("Output interval");
      write_vtu        = prm.get_bool("Write VTU");
      thickness_profile_travels.clear();
      for (const std::string &travel :
           Utilities::split_string_list(prm.get("Thickness profile travels")))
        thickness_profile_travels.push_back(
          Utilities::string_to_double(travel));
      prm.leave_subsection();

      // Equal travels are one profile; different travels with the same
      // label would write one file twice (D51).
      std::map<std::string, double> labels;
      for (const double travel : thickness_profile_travels)
      {
        const auto [it, added] = labels.emplace(travel_label(travel), travel);
        if (!added && it->second != travel)
        {
          std::ostringstream text;
          text << std::setprecision(17)
               << "Output/Thickness profile travels: " << it->second << " and "
               << travel << " both give the file name thickness_OX_"
               << it->first
               << "mm.csv; travels must differ in their first "
                  "10 significant digits";
          throw InputError(text.str());
        }
      }
    }


    std::string
    OutputParameters::travel_label(const double travel)
    {
      std::ostringstream label;
      label << std::setprecision(10) << travel;
      return label.str();
    }
  } // namespace io
} // namespace deepdraw
