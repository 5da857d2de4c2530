// FormingProblem as postprocess::SimulationAccess: what the post-processors
// (and the tests) read of the model and the run.
#include <deepdraw/problem/forming_problem.h>

namespace deepdraw
{
  namespace problem
  {
    const postprocess::SimulationAccess &
    FormingProblem::access() const
    {
      return *this;
    }


    unsigned int
    FormingProblem::last_plastic_points() const
    {
      return progress.plastic_points;
    }


    const std::vector<double> &
    FormingProblem::last_residuals() const
    {
      return progress.force_residuals;
    }


    const std::vector<adaptivity::RefinementRecord> &
    FormingProblem::refinement_records() const
    {
      return adaptation->records();
    }


    const blank::BlankGeometry &
    FormingProblem::blank() const
    {
      return parameters.geometry;
    }


    const discretisation::SheetDiscretisation &
    FormingProblem::sheet() const
    {
      return discretisation;
    }


    const discretisation::ThicknessMeasurement &
    FormingProblem::thickness() const
    {
      return thickness_measurement;
    }


    const material::HillPlasticity &
    FormingProblem::material() const
    {
      return *material_model;
    }


    const contact::ContactCoupling &
    FormingProblem::contact() const
    {
      return contact_coupling;
    }


    const state::SimulationState &
    FormingProblem::state() const
    {
      return committed;
    }


    const Vector<double> &
    FormingProblem::internal_force() const
    {
      return internal_forces;
    }


    const std::vector<unsigned int> &
    FormingProblem::reaction_faces() const
    {
      return faces_with_reactions;
    }


    const std::vector<process::Stage> &
    FormingProblem::stages() const
    {
      return parameters.stages;
    }


    unsigned int
    FormingProblem::stage_index() const
    {
      return committed.stage;
    }


    bool
    FormingProblem::stage_finished() const
    {
      return at_stage_end;
    }


    bool
    FormingProblem::landed() const
    {
      return at_landing;
    }


    double
    FormingProblem::final_load() const
    {
      return parameters.stages.back().end_load;
    }


    const postprocess::IncrementReport &
    FormingProblem::increment_report() const
    {
      return report;
    }


    double
    FormingProblem::increment_wall_time() const
    {
      return increment_timer.wall_time();
    }


    double
    FormingProblem::output_time() const
    {
      return postprocessors.output_time();
    }


    const std::string &
    FormingProblem::output_directory() const
    {
      return parameters.output.output_directory;
    }
  } // namespace problem
} // namespace deepdraw
