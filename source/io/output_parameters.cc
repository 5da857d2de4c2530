#include <deal.II/base/utilities.h>
#include <deepdraw/io/output_parameters.h>

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
                        Patterns::Double(0.),
                        "Load-parameter interval between VTU outputs "
                        "(increments land on these loads); 0 writes every "
                        "converged increment.");
      prm.declare_entry("Write VTU",
                        "true",
                        Patterns::Bool(),
                        "Write the VTU/PVD files for ParaView (the CSV "
                        "tables are always written).");
      prm.declare_entry("Thickness profile travels",
                        "15, 20",
                        Patterns::List(Patterns::Double(0.)),
                        "Final loads (values of t, mm) at which the "
                        "thickness strain along OX and OD is written "
                        "(thickness_OX_<travel>mm.csv, "
                        "thickness_OD_<travel>mm.csv; runs with tools "
                        "only); increments land on them, travels beyond "
                        "Process/Final load are ignored.");
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
    }
  } // namespace io
} // namespace deepdraw
