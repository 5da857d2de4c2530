// Where results are written (subsection Output, Output directory); the
// post-processors declare what they write and when (the other entries of
// subsection Output, doc/architecture.md).
#ifndef deepdraw_io_output_parameters_h
#define deepdraw_io_output_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <string>

namespace deepdraw
{
  namespace io
  {
    using namespace dealii;

    struct OutputParameters
    {
      std::string output_directory = "output";

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace io
} // namespace deepdraw

#endif
