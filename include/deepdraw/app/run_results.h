// What a refinement study reads back from the output folder of one run
// (doc/user_guide.md §3, §4.2): the mesh size from the console log, the cost
// from statistics.csv, and at each travel the punch force, the draw-in and
// the largest thinning on OX and OD. A value the run did not write (it
// stopped before, or has no tools) is left empty.
#ifndef deepdraw_app_run_results_h
#define deepdraw_app_run_results_h

#include <optional>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace app
  {
    using OptionalValue = std::optional<double>;

    struct TravelResults
    {
      // punch_force_N of punch_force.csv in the row of the travel.
      OptionalValue punch_force;
      // The draw-in columns NAME_mm of draw_in.csv in that row, one per
      // name asked for.
      std::vector<OptionalValue> draw_in;
      // The smallest thickness_strain (the largest thinning when negative)
      // of thickness_OX_<travel>mm.csv and of the OD file, and its s0_mm
      // (the first one where several are equal).
      OptionalValue ox_strain, ox_s0, od_strain, od_s0;
    };

    struct RunResults
    {
      // From the first line of deepdraw.log ("deepdraw: N cells, M
      // displacement unknowns, K contact unknowns, ...").
      OptionalValue cells, displacement_unknowns, contact_unknowns;
      // statistics.csv: its rows, the sums of newton_iterations and
      // cut_backs.
      OptionalValue increments, newton_iterations, cut_backs;
      // One per travel asked for.
      std::vector<TravelResults> travels;
    };

    RunResults
    read_run_results(const std::string              &directory,
                     const std::vector<double>      &travels,
                     const std::vector<std::string> &draw_in_names);
  } // namespace app
} // namespace deepdraw

#endif
