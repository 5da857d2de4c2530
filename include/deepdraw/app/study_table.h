// study.csv, the table of a refinement study (doc/user_guide.md §4.2,
// doc/decisions.md D43): one row per run, written and flushed as the run
// ends, so that a study that is stopped leaves every finished row whole.
#ifndef deepdraw_app_study_table_h
#define deepdraw_app_study_table_h

#include <deepdraw/app/run_results.h>
#include <fstream>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace app
  {
    struct StudyRow
    {
      // The values of the varied parameters, in the order of the options.
      std::vector<std::string> values;
      bool                     failed = false;
      // Stopped by a signal to the study (D179): status "interrupted".
      bool       interrupted = false;
      RunResults results;
      // Largest in-plane element size over the layer thickness.
      OptionalValue aspect_ratio;
      double        wall_seconds = 0.;
      // Why it failed, and remarks (a run with one layer).
      std::string note;
    };

    class StudyTable
    {
    public:
      // Writes the header; throws std::runtime_error if the file cannot be
      // written. With formability (the runs have the post-processor
      // "forming limits") the columns of the first crossing of the curve
      // and of the least margin follow the travels' (D174).
      StudyTable(const std::string              &filename,
                 const std::vector<std::string> &variable_names,
                 const std::vector<double>      &travels,
                 const std::vector<std::string> &draw_in_names,
                 bool                            formability = false);

      void
      add_row(const StudyRow &row);

      const std::vector<std::string> &
      columns() const;

      // Name of a column at a travel: "punch_force_N_15mm".
      static std::string
      at_travel(const std::string &quantity, double travel);

    private:
      std::ofstream            file;
      std::string              filename;
      bool                     formability;
      std::vector<std::string> column_names;
    };
  } // namespace app
} // namespace deepdraw

#endif
