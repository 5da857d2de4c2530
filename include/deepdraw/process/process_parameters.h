// The forming process (subsection Process, doc/user_guide.md): where the load
// parameter t ends (the punch travel in the square cup) and how hard the
// blank holder presses.
#ifndef deepdraw_process_process_parameters_h
#define deepdraw_process_process_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deepdraw/process/stage.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace process
  {
    using namespace dealii;

    struct ProcessParameters
    {
      // End value of the load parameter t (Process/Final load).
      double final_load = 1.;
      // Force of every force-controlled tool as an expression of t (N);
      // ContactCoupling parses and checks it.
      std::string blank_holder_force = "0";

      // With the stage slots (process::declare_stage_parameters).
      static void
      declare_parameters(ParameterHandler &prm, unsigned int n_tool_slots);
      void
      parse_parameters(ParameterHandler &prm);

      // The loads at which every expression of t is checked when the input
      // is read (D50): 0, the final load and the nine loads that divide
      // [0, final load] into ten equal parts.
      std::vector<double>
      check_loads() const;
    };
  } // namespace process
} // namespace deepdraw

#endif
