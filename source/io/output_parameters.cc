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
      prm.leave_subsection();
    }


    void
    OutputParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      output_directory = prm.get("Output directory");
      prm.leave_subsection();
    }
  } // namespace io
} // namespace deepdraw
