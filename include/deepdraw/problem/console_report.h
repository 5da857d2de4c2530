// What a run prints while it goes (doc/user_guide.md §1): the model, each
// stage, each converged increment with the time still to go, cut-backs and
// refinements; with --quiet only the summary at the end.
#ifndef deepdraw_problem_console_report_h
#define deepdraw_problem_console_report_h

#include <deal.II/base/timer.h>
#include <deepdraw/postprocess/simulation_access.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace problem
  {
    // A load as messages give it (6 significant digits).
    std::string
    format_load(double load);

    class ConsoleReport
    {
    public:
      // Starts the run's clock.
      explicit ConsoleReport(bool quiet);

      // The model at the start (or at the resumed load).
      void
      model(const postprocess::SimulationAccess &simulation,
            unsigned int                         n_unknowns,
            const std::string                   &element,
            bool                                 resumed);
      void
      stage(const postprocess::SimulationAccess &simulation);
      void
      cut_back(double load, const std::string &reason) const;
      // The increment just converged, its Newton iterations and cut-backs.
      void
      increment(const postprocess::SimulationAccess &simulation,
                unsigned int                         iterations,
                unsigned int                         cut_backs) const;
      void
      refined(unsigned int cells, unsigned int iterations) const;
      // Always printed, with the post-processors' summary lines after it.
      void
      finished(const postprocess::SimulationAccess &simulation,
               double                               seconds,
               const std::vector<std::string>      &summaries) const;

    private:
      bool          quiet;
      dealii::Timer timer;
      // The load the run started from (the mean rate of the run so far
      // estimates the time still to go).
      double first_load = 0.;
    };
  } // namespace problem
} // namespace deepdraw

#endif
