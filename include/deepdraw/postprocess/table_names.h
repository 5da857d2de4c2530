// The names of the CSV tables and of the columns that other programs read
// (the study, app/run_results.cc, and the tests): defined here once, used
// by the post-processors that write them and by the readers
// (doc/user_guide.md §3).
#ifndef deepdraw_postprocess_table_names_h
#define deepdraw_postprocess_table_names_h

#include <string>

namespace deepdraw
{
  namespace postprocess
  {
    namespace tables
    {
      // statistics.csv (post-processor "statistics").
      inline const std::string statistics        = "statistics.csv";
      inline const std::string newton_iterations = "newton_iterations";
      inline const std::string cut_backs         = "cut_backs";
      inline const std::string wall_time         = "wall_s";

      // punch_force.csv (post-processor "punch force").
      inline const std::string punch_force_table = "punch_force.csv";
      inline const std::string punch_travel      = "punch_travel_mm";
      inline const std::string punch_force       = "punch_force_N";
      inline const std::string holder_force      = "holder_force_N";
      inline const std::string holder_z          = "holder_z_mm";

      // draw_in.csv (post-processor "draw-in"): punch_travel, then one
      // column per draw-in point, its name and this suffix.
      inline const std::string draw_in_table  = "draw_in.csv";
      inline const std::string draw_in_suffix = "_mm";

      // thickness_<profile>_<travel>mm.csv (post-processor "thickness
      // profiles").
      inline const std::string profile_distance = "s0_mm";
      inline const std::string thickness_strain = "thickness_strain";

      // formability.csv (post-processor "forming limits"): the load, the
      // worst point's margin, whether it lies beyond the curve's range and
      // the least margin within it (D172). beyond_range is also a column of
      // fld_<travel>mm.csv.
      inline const std::string formability_table = "formability.csv";
      inline const std::string load              = "load";
      inline const std::string worst_margin      = "worst_margin";
      inline const std::string beyond_range      = "beyond_range";
      inline const std::string in_range_margin   = "in_range_margin";
    } // namespace tables

    // The travel as it appears in the names of the travel tables
    // (thickness_OX_<label>mm.csv): 10 significant digits, no trailing
    // zeros.
    std::string
    travel_label(double travel);

    // thickness_<profile>_<label>mm.csv
    std::string
    thickness_profile_file(const std::string &profile, double travel);
  } // namespace postprocess
} // namespace deepdraw

#endif
