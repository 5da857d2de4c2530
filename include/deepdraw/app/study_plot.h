// study.png (doc/user_guide.md §4.2, doc/decisions.md D43): every quantity
// of study.csv against the varied value, one panel per quantity (and per
// travel), drawn by gnuplot from the script study.gp written next to it.
// Failed runs are left out of the plot (their rows stay in the table).
#ifndef deepdraw_app_study_plot_h
#define deepdraw_app_study_plot_h

#include <string>
#include <vector>

namespace deepdraw
{
  namespace app
  {
    struct StudyPlotSpec
    {
      // The columns of study.csv (StudyTable::columns()).
      std::vector<std::string> columns;
      // The column plotted along x (the first varied parameter); numeric
      // values give a numeric axis, others one tick per run.
      std::string              x_column;
      bool                     x_numeric = true;
      std::string              x_label;
      std::vector<double>      travels;
      std::vector<std::string> draw_in_names;
      std::string              title;
    };

    // Writes directory/study.gp and runs gnuplot on it in directory; returns
    // what happened, for the console ("study.png written", or why not:
    // gnuplot missing or failed).
    std::string
    plot_study(const std::string &directory, const StudyPlotSpec &spec);
  } // namespace app
} // namespace deepdraw

#endif
