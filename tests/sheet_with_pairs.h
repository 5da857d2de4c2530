// A small sheet for the tests of the Newton system's assembly: nx x ny x nz
// hexahedra on [0, nx] x [0, ny] x [0, height], x = 0 held in x by
// constraints, and one contact pair [u (3), lambda (3), z] per top node,
// all of them coupled to one tool position z (the last unknown).
#ifndef deepdraw_tests_sheet_with_pairs_h
#define deepdraw_tests_sheet_with_pairs_h

#include <cmath>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>
#include <deepdraw/linear_algebra/newton_linear_system.h>
#include <vector>

namespace deepdraw_test
{
  using namespace dealii;

  // Deterministic values in [-1, 1] for the local systems of the tests.
  inline double
  pseudo_random(const unsigned int k)
  {
    return std::sin(1.3 + 0.71 * k) * std::cos(0.37 * k * k);
  }

  struct SheetWithPairs
  {
    SheetWithPairs(const unsigned int nx,
                   const unsigned int ny,
                   const unsigned int nz,
                   const double       height)
        : dof_handler(mesh)
    {
      GridGenerator::subdivided_hyper_rectangle(mesh,
                                                {nx, ny, nz},
                                                Point<3>(0, 0, 0),
                                                Point<3>(nx, ny, height),
                                                true);
      dof_handler.distribute_dofs(FESystem<3>(FE_Q<3>(1), 3));
      VectorTools::interpolate_boundary_values(dof_handler,
                                               0, // x = 0
                                               Functions::ZeroFunction<3>(3),
                                               constraints,
                                               ComponentMask(
                                                 {true, false, false}));
      constraints.close();
      find_top_pairs(height);
    }

    // Every pair's unknowns coupled with each other.
    void
    couple_pairs(DynamicSparsityPattern &dsp) const
    {
      for (const auto &dofs : pairs)
        for (const auto i : dofs)
          for (const auto j : dofs)
            dsp.add(i, j);
    }

    deepdraw::linear_algebra::SystemLayout
    layout() const
    {
      deepdraw::linear_algebra::SystemLayout layout;
      layout.dof_handler = &dof_handler;
      layout.constraints = &constraints;
      layout.n_unknowns  = n_unknowns;
      layout.add_contact_couplings
        = [this](DynamicSparsityPattern &dsp) { couple_pairs(dsp); };
      layout.multiplier_blocks = blocks;
      layout.tool_positions    = {n_unknowns - 1};
      return layout;
    }

    // The whole system's pattern as deal.II makes it (the reference).
    void
    reference_pattern(SparsityPattern &pattern) const
    {
      DynamicSparsityPattern dsp(n_unknowns, n_unknowns);
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, true);
      couple_pairs(dsp);
      pattern.copy_from(dsp);
    }

    Triangulation<3>                                  mesh;
    DoFHandler<3>                                     dof_handler;
    AffineConstraints<double>                         constraints;
    std::vector<std::vector<types::global_dof_index>> pairs;
    std::vector<deepdraw::solver::MultiplierBlock>    blocks;
    types::global_dof_index                           n_unknowns = 0;

  private:
    void
    find_top_pairs(const double height)
    {
      const types::global_dof_index        n_u = dof_handler.n_dofs();
      std::vector<bool>                    seen(n_u, false);
      std::vector<types::global_dof_index> dofs(
        dof_handler.get_fe().n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex(v)[2] > 0.9 * height && !seen[dofs[3 * v]])
          {
            seen[dofs[3 * v]] = true;
            pairs.push_back({dofs[3 * v], dofs[3 * v + 1], dofs[3 * v + 2]});
          }
      }
      const types::global_dof_index z = n_u + 3 * pairs.size();
      for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        deepdraw::solver::MultiplierBlock block;
        for (unsigned int c = 0; c < 3; ++c)
        {
          block.displacement[c] = pairs[p][c];
          block.multiplier[c]   = n_u + 3 * p + c;
          pairs[p].push_back(n_u + 3 * p + c);
        }
        pairs[p].push_back(z);
        blocks.push_back(block);
      }
      n_unknowns = z + 1;
    }
  };
} // namespace deepdraw_test

#endif
