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
      prm.leave_subsection();
    }


    void
    OutputParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      output_directory = prm.get("Output directory");
      output_interval  = prm.get_double("Output interval");
      write_vtu        = prm.get_bool("Write VTU");
      prm.leave_subsection();
    }
  } // namespace io
} // namespace deepdraw
