// The Newton iterations of the increment being solved: what statistics.csv
// and the console report of it (NewtonProgress), and newton.csv, one row per
// convergence check, failed attempts included (NewtonLog,
// doc/user_guide.md §3).
#ifndef deepdraw_problem_newton_log_h
#define deepdraw_problem_newton_log_h

#include <deepdraw/io/csv_file.h>
#include <deepdraw/solver/newton_increment.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace problem
  {
    struct NewtonProgress
    {
      // The relative residuals at each check of the last Newton run.
      std::vector<double> force_residuals;
      std::vector<double> contact_residuals;
      // Contact state changes of the attempt so far, of its last assembly
      // alone (NewtonSystem::state_changes, D91), and those written to
      // newton.csv already.
      unsigned int contact_changes       = 0;
      unsigned int last_assembly_changes = 0;
      unsigned int changes_reported      = 0;
      // Quadrature points that yielded in the last assembly, and elements
      // condensed with unconverged enhanced parameters in it (D189).
      unsigned int plastic_points   = 0;
      unsigned int pending_elements = 0;
      // Of the increment's attempts so far (s).
      double assembly_time = 0.;
      double solve_time    = 0.;
      // Rows of a re-equilibration belong to the increment just converged.
      bool reequilibrating = false;

      // A new attempt: no residuals, no changes.
      void
      start_attempt();
      // The residual histories of a finished Newton run.
      void
      keep_residuals(const solver::NewtonIncrement &newton);
      // The last residuals (0 if none).
      double
      last_force_residual() const;
      double
      last_contact_residual() const;
    };

    class NewtonLog
    {
    public:
      // newton.csv in directory (resume: appends).
      void
      open(const std::string &directory, bool resume);
      // One convergence check of the increment that ends at load.
      void
      add(unsigned int                    increment,
          double                          load,
          unsigned int                    iterations,
          const solver::ResidualMeasures &residuals,
          double                          relative_correction,
          unsigned int                    contact_changes);

    private:
      io::CsvFile file;
    };
  } // namespace problem
} // namespace deepdraw

#endif
