// FormingProblem: its construction and what tests and benchmarks call
// directly. The run is in forming_problem_run.cc, one increment in
// forming_problem_newton.cc.
#include <deepdraw/problem/forming_problem.h>

namespace deepdraw
{
  namespace problem
  {
    void
    FormingProblem::declare_parameters(ParameterHandler &prm)
    {
      ModelParameters::declare_parameters(prm);
    }


    FormingProblem::FormingProblem(ParameterHandler  &prm,
                                   const std::string &input_directory)
    {
      parameters.parse_parameters(prm, input_directory);
      postprocessors.parse_parameters(prm);
      model = std::make_unique<SheetModel>(prm, parameters, input_directory);
      adaptation
        = std::make_unique<adaptivity::MeshAdaptation>(parameters.adaptivity);
      view
        = std::make_unique<SimulationView>(*model, run_record, postprocessors);
      newton_unknowns.reinit(model->n_unknowns());
      postprocessors.initialize(*view);
    }


    const postprocess::SimulationAccess &
    FormingProblem::access() const
    {
      return *view;
    }


    void
    FormingProblem::prepare_increment(const double old_load,
                                      const double new_load)
    {
      model->prepare_increment(old_load, new_load);
      start_load  = old_load;
      target_load = new_load;
    }


    bool
    FormingProblem::assemble_system(const Vector<double> &unknowns)
    {
      AffineConstraints<double> none;
      none.close();
      return assemble(unknowns, none, true) == IncrementOutcome::converged;
    }


    bool
    FormingProblem::evaluate_residual(const Vector<double> &unknowns,
                                      Vector<double>       &residual,
                                      FullMatrix<double>   *tangent)
    {
      AffineConstraints<double> none;
      none.close();
      const IncrementOutcome status
        = assemble(unknowns, none, tangent != nullptr);
      // Without constraints rhs = -r for all equations, contact included.
      residual = model->linear_system().rhs();
      residual *= -1.;
      if (tangent != nullptr)
        model->linear_system().copy_to(*tangent);
      return status == IncrementOutcome::converged;
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
  } // namespace problem
} // namespace deepdraw
