// What a refinement study reads back from the output folder of one run
// (doc/user_guide.md §3, §4.2): the mesh size from the console log, the cost
// from statistics.csv, at each travel the punch force, the draw-in and the
// largest thinning on OX and OD, and from formability.csv the first
// crossing of the forming-limit curve and the least margin. A value the run
// did not write (it stopped before, has no tools, or no forming limits) is
// left empty.
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
      // formability.csv (post-processor "forming limits", D174): the load
      // of the first row whose worst margin is <= 0 and whether that point
      // lies beyond the curve's range (1) or not (0); the load of the first
      // row whose least margin within the range is <= 0; the least worst
      // margin of all rows, and of the margins within the range. Empty
      // where the curve was not crossed or the table is absent.
      OptionalValue flc_first_crossing, flc_first_crossing_beyond_range,
        flc_first_crossing_in_range, flc_least_margin,
        flc_least_margin_in_range;
    };

    RunResults
    read_run_results(const std::string              &directory,
                     const std::vector<double>      &travels,
                     const std::vector<std::string> &draw_in_names);
  } // namespace app
} // namespace deepdraw

#endif
