// Adaptive refinement during the run (subsection Adaptivity, doc/theory.md
// §8, D80-D85): after every Refinement interval converged increments (not
// the last of the run) the indicator flags cells, the mesh is refined and
// the committed state carried over (state_transfer.h); the problem then
// rebuilds its system, carries the contact pairs over and re-equilibrates
// at the same load, and adaptivity.csv gets a row.
#ifndef deepdraw_adaptivity_mesh_adaptation_h
#define deepdraw_adaptivity_mesh_adaptation_h

#include <deal.II/base/timer.h>
#include <deepdraw/adaptivity/adaptivity_parameters.h>
#include <deepdraw/contact/contact_coupling.h>
#include <deepdraw/discretisation/sheet_discretisation.h>
#include <deepdraw/fe/vertex_parents.h>
#include <deepdraw/io/csv_file.h>
#include <deepdraw/material/elasto_plasticity.h>
#include <deepdraw/state/simulation_state.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace adaptivity
  {
    // One refinement (adaptivity.csv).
    struct RefinementRecord
    {
      unsigned int cycle;
      unsigned int increment;
      double       load;
      unsigned int cells_before;
      unsigned int cells_after;
      unsigned int hanging_vertices;
      // Force and contact residuals of the transferred state, before the
      // re-equilibration, and its Newton iterations and last residual.
      double       initial_force_residual;
      double       initial_contact_residual;
      unsigned int iterations;
      double       force_residual;
      double       wall_time;
    };

    class MeshAdaptation
    {
    public:
      explicit MeshAdaptation(const AdaptivityParameters &parameters);

      // Opens adaptivity.csv (adaptive runs only; resume: appends).
      void
      open(const std::string &directory, bool resume);

      // After the converged increment of `state`: if a refinement is due
      // (every Refinement interval increments, not after the last), flags
      // the cells the indicator selects (the tools that take part count for
      // the tool curvature) and records them in state.refinements (D84).
      // Returns whether any cell is flagged.
      bool
      flag_cells(discretisation::SheetDiscretisation &sheet,
                 state::SimulationState              &state,
                 const contact::ContactCoupling      &contact,
                 double                               sheet_thickness,
                 bool                                 last_increment);

      // Refines the flagged cells and carries the committed state over
      // (history, displacements); returns the parents of every vertex. The
      // state holds the records of this rank's cells (D217), with enhanced
      // parameters or not, before and after.
      std::vector<fe::VertexParents>
      refine(discretisation::SheetDiscretisation &sheet,
             state::SimulationState              &state,
             const material::ElastoPlasticity    &material,
             bool                                 enhanced_parameters) const;

      // The row of the refinement after its re-equilibration: the Newton
      // residuals at each of its checks and its iterations.
      void
      record(const discretisation::SheetDiscretisation &sheet,
             types::global_dof_index                    n_unknowns,
             const std::vector<double>                 &force_residuals,
             const std::vector<double>                 &contact_residuals,
             unsigned int                               iterations);

      const std::vector<RefinementRecord> &
      records() const;

    private:
      // The indicator per active cell, scaled so that the cells to refine
      // are those above 1 (value / threshold; the larger of the two for the
      // combined indicator, D95).
      std::vector<double>
      scaled_indicator(const discretisation::SheetDiscretisation &sheet,
                       const state::SimulationState              &state,
                       const contact::ContactCoupling            &contact,
                       double sheet_thickness) const;

      AdaptivityParameters          parameters;
      std::vector<RefinementRecord> history;
      // The refinement under way (flag_cells() to record()).
      RefinementRecord pending{};
      dealii::Timer    timer;
      io::CsvFile      file;
    };
  } // namespace adaptivity
} // namespace deepdraw

#endif
