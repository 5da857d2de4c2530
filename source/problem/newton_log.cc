#include <deepdraw/problem/newton_log.h>

namespace deepdraw
{
  namespace problem
  {
    void
    NewtonProgress::start_attempt()
    {
      force_residuals.clear();
      contact_residuals.clear();
      contact_changes  = 0;
      changes_reported = 0;
    }


    void
    NewtonProgress::keep_residuals(const solver::NewtonIncrement &newton)
    {
      force_residuals   = newton.force_residuals();
      contact_residuals = newton.contact_residuals();
    }


    double
    NewtonProgress::last_force_residual() const
    {
      return force_residuals.empty() ? 0. : force_residuals.back();
    }


    double
    NewtonProgress::last_contact_residual() const
    {
      return contact_residuals.empty() ? 0. : contact_residuals.back();
    }


    void
    NewtonLog::open(const std::string &directory, const bool resume)
    {
      file.open(directory + "/newton.csv",
                {"increment",
                 "load",
                 "iteration",
                 "force_residual",
                 "contact_residual",
                 "correction",
                 "contact_changes"},
                resume);
    }


    void
    NewtonLog::add(const unsigned int              increment,
                   const double                    load,
                   const unsigned int              iterations,
                   const solver::ResidualMeasures &residuals,
                   const double                    relative_correction,
                   const unsigned int              contact_changes)
    {
      file.add_row({double(increment),
                    load,
                    double(iterations),
                    residuals.force,
                    residuals.contact,
                    relative_correction,
                    double(contact_changes)});
    }
  } // namespace problem
} // namespace deepdraw
