// The small mesh with a Q1 vector DoFHandler and a SimulationState that the
// state-transfer tests refine (state_transfer.cc, smooth_transfer.cc).
#ifndef deepdraw_tests_adaptivity_transfer_block_h
#define deepdraw_tests_adaptivity_transfer_block_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/state/simulation_state.h>

namespace deepdraw_test
{
  struct TransferBlock
  {
    dealii::Triangulation<3>         triangulation;
    dealii::FESystem<3>              fe{dealii::FE_Q<3>(1), 3};
    dealii::DoFHandler<3>            dof_handler{triangulation};
    deepdraw::state::SimulationState state;

    // Distributes the dofs and sets state.total_displacement at every
    // vertex to displacement(x, vertex index) (a Tensor<1, 3>).
    template <typename Displacement>
    void
    set_total_displacement(const Displacement &displacement)
    {
      dof_handler.distribute_dofs(fe);
      state.total_displacement.reinit(dof_handler.n_dofs());
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
        {
          const dealii::Tensor<1, 3> u
            = displacement(cell->vertex(v), cell->vertex_index(v));
          for (unsigned int c = 0; c < 3; ++c)
            state.total_displacement[cell->vertex_dof_index(v, c)] = u[c];
        }
    }
  };
} // namespace deepdraw_test

#endif
