// Input checks of FormingProblem that need several subsections at once
// (doc/user_guide.md §5.2, decisions D50 and D53); each subsection checks
// its own entries when it is parsed.
#include <deepdraw/blank/memory_estimate.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/problem/forming_problem.h>
#include <iomanip>
#include <sstream>

namespace deepdraw
{
  namespace problem
  {
    namespace
    {
      // A run needs at least Final load / Maximum increment increments and
      // writes up to Final load / Output interval VTU files (D50).
      constexpr double max_increments = 1e6;
      constexpr double max_outputs    = 1e5;
    } // namespace


    void
    FormingProblem::check_input() const
    {
      // Every expression of t at 11 loads from 0 to the final load (D50):
      // a boundary condition, translation or force without a value there
      // is named now, not found later as "residual is not a number".
      const std::vector<double> loads = process_parameters.check_loads();
      prescribed.check_values(geometry, loads);
      contact.check_values(
        loads,
        geometry.diagonal(),
        process::PrescribedDisplacements::max_relative_displacement
          * geometry.largest_extent());

      const double       final_load = process_parameters.final_load;
      std::ostringstream text;
      text << std::setprecision(6);
      if (final_load / increment_parameters.maximum_increment > max_increments)
      {
        text << "Process/Final load = " << final_load << " needs more than "
             << max_increments
             << " increments of Load stepping/Maximum increment = "
             << increment_parameters.maximum_increment
             << "; allowed are Final load / Maximum increment <= "
             << max_increments;
        throw InputError(text.str());
      }
      const double interval = output_parameters.output_interval;
      if (interval > 0. && final_load / interval > max_outputs)
      {
        text << "Output/Output interval = " << interval << " would write "
             << final_load / interval
             << " VTU files up to Process/Final load = " << final_load
             << "; allowed are Final load / Output interval <= " << max_outputs
             << " (0 writes one per increment)";
        throw InputError(text.str());
      }

      // The mesh is made only if it fits into the memory (D53).
      blank::check_memory(geometry,
                          contact.active() ? contact.tool_definitions().size()
                                           : 0);
    }
  } // namespace problem
} // namespace deepdraw
