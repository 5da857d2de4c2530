// The small mesh with a Q1 vector DoFHandler and a SimulationState that the
// state-transfer tests refine (state_transfer.cc, smooth_transfer.cc).
#ifndef deepdraw_tests_adaptivity_transfer_block_h
#define deepdraw_tests_adaptivity_transfer_block_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/problem/simulation_state.h>

namespace deepdraw_test
{
  struct TransferBlock
  {
    dealii::Triangulation<3>           triangulation;
    dealii::FESystem<3>                fe{dealii::FE_Q<3>(1), 3};
    dealii::DoFHandler<3>              dof_handler{triangulation};
    deepdraw::problem::SimulationState state;
  };
} // namespace deepdraw_test

#endif
