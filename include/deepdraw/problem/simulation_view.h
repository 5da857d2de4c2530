// The problem's postprocess::SimulationAccess: the model (SheetModel) as it
// stands after the last converged increment and the figures of the run
// (RunRecord), read-only.
#ifndef deepdraw_problem_simulation_view_h
#define deepdraw_problem_simulation_view_h

#include <deal.II/base/timer.h>
#include <deepdraw/postprocess/manager.h>
#include <deepdraw/postprocess/simulation_access.h>
#include <deepdraw/problem/newton_log.h>
#include <deepdraw/problem/sheet_model.h>

namespace deepdraw
{
  namespace problem
  {
    // What the run knows of its last converged increment.
    struct RunRecord
    {
      postprocess::IncrementReport report;
      // Since the increment's first attempt began.
      Timer increment_timer;
      // It landed on a requested load / ended its stage.
      bool at_landing   = false;
      bool at_stage_end = false;
      // The linear solver's counts at the last report, the contact
      // coupling's time when the increment began (s).
      solver::LinearSolver::Statistics reported_solver_statistics;
      double                           contact_time_at_start = 0.;

      // An increment's first attempt begins; contact_time: the contact
      // coupling's time so far.
      void
      start_increment(double contact_time);
      // The report of an increment converged with iterations after
      // cut_backs, from its Newton progress, the linear solver's counts
      // and the contact coupling's time so far.
      void
      record_increment(double                                  load_increment,
                       unsigned int                            iterations,
                       unsigned int                            cut_backs,
                       const NewtonProgress                   &progress,
                       const solver::LinearSolver::Statistics &statistics,
                       double                                  contact_time);
    };

    class SimulationView : public postprocess::SimulationAccess
    {
    public:
      SimulationView(const SheetModel           &model,
                     const RunRecord            &run,
                     const postprocess::Manager &postprocessors);

      const blank::BlankGeometry &
      blank() const override;
      const discretisation::SheetDiscretisation &
      sheet() const override;
      const discretisation::ThicknessMeasurement &
      thickness() const override;
      const material::ElastoPlasticity &
      material() const override;
      const contact::ContactCoupling &
      contact() const override;
      const state::SimulationState &
      state() const override;
      const Vector<double> &
      internal_force() const override;
      const std::vector<unsigned int> &
      reaction_faces() const override;
      const std::vector<process::Stage> &
      stages() const override;
      unsigned int
      stage_index() const override;
      bool
      stage_finished() const override;
      bool
      landed() const override;
      double
      final_load() const override;
      const postprocess::IncrementReport &
      increment_report() const override;
      double
      increment_wall_time() const override;
      double
      output_time() const override;
      const std::string &
      output_directory() const override;
      const postprocess::Interface *
      find_postprocessor(const std::string &name) const override;

    private:
      const SheetModel           &model;
      const RunRecord            &run;
      const postprocess::Manager &postprocessors;
    };
  } // namespace problem
} // namespace deepdraw

#endif
