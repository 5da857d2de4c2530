// What a post-processor may read of the simulation (doc/architecture.md,
// "Post-processors"; the model is ASPECT's SimulatorAccess): the model as
// it stands after the last converged increment, the process and its stage,
// and the figures of the increment. Read-only; the problem implements it.
#ifndef deepdraw_postprocess_simulation_access_h
#define deepdraw_postprocess_simulation_access_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/blank/blank_geometry.h>
#include <deepdraw/contact/contact_coupling.h>
#include <deepdraw/discretisation/sheet_discretisation.h>
#include <deepdraw/discretisation/thickness_measurement.h>
#include <deepdraw/material/elasto_plasticity.h>
#include <deepdraw/process/stage.h>
#include <deepdraw/state/simulation_state.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace postprocess
  {
    using namespace dealii;

    class Interface;

    // The figures of the last converged increment (statistics.csv).
    struct IncrementReport
    {
      double       load_increment   = 0.;
      unsigned int iterations       = 0;
      unsigned int cut_backs        = 0;
      double       force_residual   = 0.;
      double       contact_residual = 0.;
      unsigned int plastic_points   = 0;
      unsigned int contact_changes  = 0;
      // Wall times of its attempts (s).
      double assembly_time = 0.;
      double contact_time  = 0.;
      double solve_time    = 0.;
      // The last linear solve's factorised unknowns, and the orderings
      // computed since the last report.
      double       factorized_unknowns = 0.;
      unsigned int symbolic_analyses   = 0;
    };

    class SimulationAccess
    {
    public:
      virtual ~SimulationAccess() = default;

      // The model.
      virtual const blank::BlankGeometry &
      blank() const = 0;
      // The mesh on x_t (the configuration of the last converged
      // increment), the initial vertices, the dofs.
      virtual const discretisation::SheetDiscretisation &
      sheet() const = 0;
      virtual const discretisation::ThicknessMeasurement &
      thickness() const = 0;
      virtual const material::ElastoPlasticity &
      material() const = 0;
      virtual const contact::ContactCoupling &
      contact() const = 0;
      // The committed state: load, increment, total displacement, history.
      // Its history and enhanced parameters are those of the cells this
      // rank evaluates, at their slots in sheet().owned_cells() (every cell
      // with one rank, D217).
      virtual const state::SimulationState &
      state() const = 0;
      // Internal nodal forces of the last assembly (reactions at
      // constrained dofs).
      virtual const Vector<double> &
      internal_force() const = 0;
      // The force through a face of the blank (by boundary id): the sum of
      // the internal forces of its nodes (a reaction where the face is
      // prescribed).
      Tensor<1, 3>
      face_reaction(const unsigned int boundary_id) const
      {
        return sheet().face_reaction(boundary_id, internal_force());
      }
      // The faces that carry a prescribed displacement in some stage
      // (reactions.csv), by boundary id.
      virtual const std::vector<unsigned int> &
      reaction_faces() const = 0;

      // The process.
      virtual const std::vector<process::Stage> &
      stages() const = 0;
      // The stage the last increment belongs to (its index in stages()),
      // and whether that increment ended it.
      virtual unsigned int
      stage_index() const = 0;
      virtual bool
      stage_finished() const = 0;
      // Whether the last increment landed on a load a post-processor asked
      // for (requested_loads) or on the end of its stage.
      virtual bool
      landed() const = 0;
      // The end of the last stage.
      virtual double
      final_load() const = 0;

      // The run.
      virtual const IncrementReport &
      increment_report() const = 0;
      // Wall time of the increment so far, its attempts included, and of
      // its outputs so far (s).
      virtual double
      increment_wall_time() const = 0;
      virtual double
      output_time() const = 0;
      virtual const std::string &
      output_directory() const = 0;

      // The post-processor of this run listed under name (in Postprocess/
      // List of postprocessors), nullptr if it is not listed: a VTU field
      // reads the results of one this way (D141).
      virtual const Interface *
      find_postprocessor(const std::string &name) const = 0;
    };
  } // namespace postprocess
} // namespace deepdraw

#endif
