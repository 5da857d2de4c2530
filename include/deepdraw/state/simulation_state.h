// The committed state of a forming simulation: what has to survive a
// restart or a mesh change (doc/architecture.md, "The state of a
// simulation"). FormingProblem keeps it here and commits it when an
// increment converges; mesh topology, dofs and constraints are rebuilt from
// the prm, the vertex positions are stored.
#ifndef deepdraw_state_simulation_state_h
#define deepdraw_state_simulation_state_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/contact/contact_history.h>
#include <deepdraw/fe/hexahedron_element.h>
#include <deepdraw/fe/quadrature_point_update.h>
#include <iosfwd>
#include <vector>

namespace deepdraw
{
  namespace state
  {
    using namespace dealii;

    struct SimulationState
    {
      // Load parameter t of the last converged increment, and that
      // increment's step.
      double       load                = 0.;
      double       last_load_increment = 0.;
      unsigned int increment_number    = 0;
      // Size of the next attempt proposed by the load stepping (before it
      // is clipped to an output load): solver::IncrementControl::State.
      double next_increment = 0.;
      // Current position of every vertex (the configuration x_t).
      std::vector<Point<3>> vertices;
      // Total displacement since t = 0 (displacement dofs).
      Vector<double> total_displacement;
      // Newton unknowns [du | lambda | z] of the last converged increment
      // and of the one before (extrapolation predictor).
      Vector<double> converged_solution;
      Vector<double> previous_converged_solution;
      // Quadrature-point history (8 points per cell) and the element-internal
      // unknowns per cell (incompatible modes), of the cells this rank
      // evaluates in their active-cell order (every cell with one rank, and
      // in a checkpoint; parallel::OwnedCells, D217).
      std::vector<fe::QuadraturePointHistory> history;
      std::vector<fe::EnhancedParameters>     enhanced_parameters;
      contact::ContactHistory                 contact;
      // Adaptive refinement (D84): per refinement cycle, the cells flagged
      // on the mesh of that cycle as (level, index, deal.II refinement
      // case); a resume replays them on the blank's mesh.
      std::vector<std::vector<std::array<int, 3>>> refinements;
      // The stage of the process (process::Stage, by its place in the
      // list) the increments belong to, and whether it has ended (its end
      // outputs written, the next stage not yet begun).
      unsigned int stage           = 0;
      bool         stage_completed = false;
      // The forces the model carried when the stage began (the reference
      // force F_ref of doc/theory.md §5.2 is at least this, D102; 0 in the
      // first stage).
      double stage_force_scale = 0.;
      // The force scale of the model when the stage ended (negative: not
      // known, a checkpoint of state format 4); the next stage's
      // stage_force_scale, the same after a resume between the stages.
      double end_force_scale = -1.;
      // A force release (D150): the nodal forces on the sheet at the end of
      // the stage before it (displacement dofs), released as loads that
      // fall linearly to zero over the stage; empty in other stages.
      Vector<double> release_loads;
      // A release stage: the sheet node of each of its supports, found at
      // the stage's start (process::ReleaseSupport, D151).
      std::vector<unsigned int> release_support_vertices;
      // A release stage: the total displacement at its start (the
      // springback is the displacement since then).
      Vector<double> release_start_displacement;

      // Binary image of all of the above; read() throws std::runtime_error
      // if the stream is not one (or was cut short).
      void
      write(std::ostream &stream) const;
      void
      read(std::istream &stream);
    };
  } // namespace state
} // namespace deepdraw

#endif
