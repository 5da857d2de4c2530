#include <deepdraw/problem/simulation_view.h>

namespace deepdraw
{
  namespace problem
  {
    void
    RunRecord::start_increment(const double contact_time)
    {
      contact_time_at_start = contact_time;
      increment_timer.restart();
    }


    void
    RunRecord::record_increment(
      const double                            load_increment,
      const unsigned int                      iterations,
      const unsigned int                      cut_backs,
      const NewtonProgress                   &progress,
      const solver::LinearSolver::Statistics &statistics,
      const double                            contact_time)
    {
      report.contact_time        = contact_time - contact_time_at_start;
      report.load_increment      = load_increment;
      report.iterations          = iterations;
      report.cut_backs           = cut_backs;
      report.force_residual      = progress.last_force_residual();
      report.contact_residual    = progress.last_contact_residual();
      report.plastic_points      = progress.plastic_points;
      report.contact_changes     = progress.contact_changes;
      report.assembly_time       = progress.assembly_time;
      report.solve_time          = progress.solve_time;
      report.factorized_unknowns = statistics.factorized_unknowns;
      report.symbolic_analyses   = statistics.symbolic_analyses
                                 - reported_solver_statistics.symbolic_analyses;
      reported_solver_statistics = statistics;
    }


    SimulationView::SimulationView(const SheetModel           &model,
                                   const RunRecord            &run,
                                   const postprocess::Manager &postprocessors)
        : model(model)
        , run(run)
        , postprocessors(postprocessors)
    {
    }


    const blank::BlankGeometry &
    SimulationView::blank() const
    {
      return model.model_parameters().geometry;
    }


    const discretisation::SheetDiscretisation &
    SimulationView::sheet() const
    {
      return model.sheet();
    }


    const discretisation::ThicknessMeasurement &
    SimulationView::thickness() const
    {
      return model.thickness();
    }


    const material::ElastoPlasticity &
    SimulationView::material() const
    {
      return model.material();
    }


    const contact::ContactCoupling &
    SimulationView::contact() const
    {
      return model.contact();
    }


    const state::SimulationState &
    SimulationView::state() const
    {
      return model.state();
    }


    const Vector<double> &
    SimulationView::internal_force() const
    {
      return model.internal_force();
    }


    const std::vector<unsigned int> &
    SimulationView::reaction_faces() const
    {
      return model.reaction_faces();
    }


    const std::vector<process::Stage> &
    SimulationView::stages() const
    {
      return model.model_parameters().stages;
    }


    unsigned int
    SimulationView::stage_index() const
    {
      return model.state().stage;
    }


    bool
    SimulationView::stage_finished() const
    {
      return run.at_stage_end;
    }


    bool
    SimulationView::landed() const
    {
      return run.at_landing;
    }


    double
    SimulationView::final_load() const
    {
      return stages().back().end_load;
    }


    const postprocess::IncrementReport &
    SimulationView::increment_report() const
    {
      return run.report;
    }


    double
    SimulationView::increment_wall_time() const
    {
      return run.increment_timer.wall_time();
    }


    double
    SimulationView::output_time() const
    {
      return postprocessors.output_time();
    }


    const std::string &
    SimulationView::output_directory() const
    {
      return model.model_parameters().output.output_directory;
    }


    const postprocess::Interface *
    SimulationView::find_postprocessor(const std::string &name) const
    {
      return postprocessors.find(name);
    }
  } // namespace problem
} // namespace deepdraw
