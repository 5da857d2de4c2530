// Transfer of a state::SimulationState to a refined mesh (doc/theory.md §8,
// doc/decisions.md D57): the mesh change that adaptive refinement
// (subsection Adaptivity, issue 13) and a refined restart build on.
#ifndef deepdraw_adaptivity_state_transfer_h
#define deepdraw_adaptivity_state_transfer_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/material/elasto_plasticity.h>
#include <deepdraw/parallel/owned_cells.h>
#include <deepdraw/state/simulation_state.h>

namespace deepdraw
{
  namespace adaptivity
  {
    using namespace dealii;

    // Where the new vertices go (D87): `linear` at the Q1 interpolation of
    // the parents (on the chord of a bent coarse edge), `smooth` on the
    // curves through the old vertices along the mesh lines
    // (vertex_placement.h).
    enum class VertexPlacement
    {
      linear,
      smooth
    };

    // How a child point's history is made (D57, D88): `nearest` the whole
    // state of the parent's nearest Gauss point, `interpolated` the
    // trilinear interpolation of the parent's 8 points, made admissible
    // (history_interpolation.h).
    enum class HistoryTransfer
    {
      nearest,
      interpolated
    };

    // The defaults are deal.II's placement and D57's history; adaptive runs
    // take theirs from subsection Adaptivity (smooth placement by default,
    // D89).
    struct TransferOptions
    {
      VertexPlacement vertex_placement = VertexPlacement::linear;
      HistoryTransfer history          = HistoryTransfer::nearest;
      // Needed by HistoryTransfer::interpolated (the yield surface).
      const material::ElastoPlasticity *material = nullptr;
      // The cells whose records (history, enhanced parameters) `state`
      // holds: every cell where nullptr; under mpirun this rank's cells of
      // the mesh before refinement (D220), with the points per cell and
      // whether the cells have enhanced parameters, which a rank without
      // cells cannot tell from its records.
      const parallel::OwnedCells *held_cells          = nullptr;
      unsigned int                points_per_cell     = 0;
      bool                        enhanced_parameters = false;
    };

    // Refines the triangulation as its refine flags say (isotropic, or any
    // anisotropic case for the history; coarsening flags are rejected) and
    // carries the state over:
    // - displacement fields (total displacement, the displacement blocks
    //   of the last two Newton solutions) by Q1 interpolation, exact
    //   because the coarse Q1 space is contained in the refined one; the
    //   contact blocks [lambda | z] are dropped, the caller appends those of
    //   the refined mesh's contact pairs;
    // - quadrature-point history: each child point takes the values of the
    //   parent's Gauss point nearest to it in the parent's reference cell
    //   (constant fields are exact, rotations stay orthogonal and every
    //   point keeps a converged, admissible material state), or their
    //   trilinear interpolation (options.history);
    // - enhanced parameters: cells that were not refined keep theirs,
    //   children start from zero (they belong to one increment);
    // - vertices: the refined mesh's (it is in the configuration x_t), the
    //   new non-hanging ones moved onto the smooth curves of
    //   options.vertex_placement; the total displacement of a moved vertex
    //   moves with it (its initial position stays the Q1 interpolation of
    //   the blank's), the increments of the Newton solutions do not.
    // The DoFHandler is redistributed with its element. A rank that holds
    // some cells' records (options.held_cells) makes those of their
    // children and keeps them, in the new cells' order; the result says
    // which rank holds each new active cell's records (this rank for every
    // cell where options.held_cells is nullptr). Throws std::logic_error
    // if a coarsening flag is set or the state does not belong to the mesh,
    // std::invalid_argument if options.history needs the material and it
    // is missing.
    std::vector<unsigned int>
    refine_and_transfer(Triangulation<3>       &triangulation,
                        DoFHandler<3>          &dof_handler,
                        state::SimulationState &state,
                        const TransferOptions  &options = TransferOptions());
  } // namespace adaptivity
} // namespace deepdraw

#endif
