// Where and how often results are written (subsection Output).
#ifndef deepdraw_io_output_parameters_h
#define deepdraw_io_output_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace io
  {
    using namespace dealii;

    struct OutputParameters
    {
      std::string output_directory = "output";
      double      output_interval  = 0.;
      bool        write_vtu        = true;
      // Final loads (mm) at which the thickness profiles are written.
      std::vector<double> thickness_profile_travels = {15., 20.};

      static void
      declare_parameters(ParameterHandler &prm);
      // Throws InputError if two travels give the same file name.
      void
      parse_parameters(ParameterHandler &prm);

      // The travel as it appears in thickness_OX_<label>mm.csv: 10
      // significant digits, no trailing zeros.
      static std::string
      travel_label(double travel);
    };
  } // namespace io
} // namespace deepdraw

#endif
