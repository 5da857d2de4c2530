// The exact elimination of the contact multipliers (D90,
// solver::MultiplierCondensation) against the whole system, on a small
// Newton-like system assembled as ContactCoupling assembles it: a
// nonsymmetric stiffness of 14 nodes, pairs of a displacement-controlled
// tool on nodes 2-10 and of a force-controlled tool (position z) on nodes
// 7-11, their blocks from the real Alart–Curnier law in every state (open,
// stick, slip, tilted normals), a clamped node and one symmetry-plane
// component with its multiplier constrained.
// Expected, independently of the condensation: the whole system's LU
// solution. Checked:
// - the condensed solve is used, factorises the 42 displacements only, and
//   its solution equals the whole one and satisfies the whole system to
//   1e-13 relative (both reach about 1e-15; the tolerance leaves the
//   round-off of the products with r = 50 room);
// - a node touching both tools cannot be condensed: the solver falls back
//   to the whole system, with the same solution.
#include "test_utilities.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deepdraw/contact/alart_curnier_law.h>
#include <deepdraw/solver/linear_solver.h>
#include <vector>

using namespace dealii;
using namespace deepdraw;
using namespace deepdraw_test;

namespace
{
  constexpr unsigned int n_nodes = 14;
  constexpr unsigned int n_u     = 3 * n_nodes;
  constexpr double       r       = 50.;

  struct TestPair
  {
    unsigned int node;
    bool         force_controlled;
    // The state the law is evaluated at.
    Tensor<1, 3> multiplier, gap, normal;
  };

  // A value in [-1, 1] that depends on i and j only.
  double
  pseudo_random(const unsigned int i, const unsigned int j)
  {
    return std::sin(12.9898 * i + 78.233 * j + 0.5);
  }

  Tensor<1, 3>
  unit(const double x, const double y, const double z)
  {
    Tensor<1, 3> v({x, y, z});
    return v / v.norm();
  }

  std::vector<TestPair>
  make_pairs(const bool node_on_both_tools)
  {
    std::vector<TestPair> pairs;
    const Tensor<1, 3>    up = unit(0.1, -0.2, 1.);
    for (unsigned int node = 2; node <= 10; ++node)
    {
      TestPair           pair{node, false, {}, {}, unit(0.05 * node, 0.1, 1.)};
      const Tensor<1, 3> t = unit(1., 0.3, -0.05 * node - 0.03);
      switch (node % 3)
      {
        case 0: // open: separated, no force
          pair.gap = 0.2 * pair.normal;
          break;
        case 1: // stick: |lambda_T| well inside the cone
          pair.multiplier = 5. * pair.normal + 0.3 * t;
          pair.gap        = -0.01 * pair.normal;
          break;
        case 2: // slip: outside the cone
          pair.multiplier = 5. * pair.normal + 3. * t;
          pair.gap        = -0.02 * pair.normal + 0.01 * t;
          break;
      }
      // Nodes 7-10 face the holder too: there this tool's pair is open,
      // unless a node on both tools is wanted: then node 7 slips on both
      // (normals far apart, else the pair of constraints is singular).
      if (node == 7 && node_on_both_tools)
      {
        pair.multiplier = 5. * pair.normal + 3. * t;
        pair.gap        = -0.02 * pair.normal + 0.01 * t;
      }
      else if (node >= 7)
      {
        pair.multiplier = Tensor<1, 3>();
        pair.gap        = 0.3 * pair.normal;
      }
      pairs.push_back(pair);
    }
    for (unsigned int node = 7; node <= 11; ++node)
    {
      TestPair           pair{node, true, {}, {}, up};
      const Tensor<1, 3> t = unit(0.4, 1., 0.2);
      pair.multiplier
        = 4. * pair.normal + (node % 2 == 0 || node == 7 ? 2.5 : 0.2) * t;
      pair.gap = -0.015 * pair.normal;
      pairs.push_back(pair);
    }
    return pairs;
  }

  struct TestSystem
  {
    SparsityPattern                      pattern;
    SparseMatrix<double>                 matrix;
    Vector<double>                       rhs;
    std::vector<solver::MultiplierBlock> blocks;
    std::vector<bool>                    constrained;
    types::global_dof_index              z = 0;
  };

  void
  assemble(const std::vector<TestPair> &pairs, TestSystem &system)
  {
    const types::global_dof_index n = n_u + 3 * pairs.size() + 1;
    system.z                        = n - 1;
    const Tensor<1, 3>             axis({0., 0., -1.});
    const contact::AlartCurnierLaw law(0.2);

    // Constraints: node 0 clamped, node 4's x with its multiplier (the
    // first pair is on node 2, so node 4's, a sticking one, is pair 2).
    AffineConstraints<double> constraints;
    constraints.reinit(complete_index_set(n));
    for (unsigned int c = 0; c < 3; ++c)
      constraints.add_line(c);
    constraints.add_line(3 * 4);
    constraints.add_line(n_u + 3 * 2);
    constraints.close();
    system.constrained.assign(n, false);
    for (const auto &line : constraints.get_lines())
      system.constrained[line.index] = true;

    DynamicSparsityPattern dsp(n, n);
    for (unsigned int a = 0; a < n_nodes; ++a)
      for (unsigned int b = (a > 2 ? a - 2 : 0);
           b <= std::min(a + 2, n_nodes - 1);
           ++b)
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            dsp.add(3 * a + i, 3 * b + j);
    system.blocks.clear();
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      std::vector<types::global_dof_index> dofs;
      solver::MultiplierBlock              block;
      for (unsigned int c = 0; c < 3; ++c)
      {
        block.displacement[c] = 3 * pairs[p].node + c;
        block.multiplier[c]   = n_u + 3 * p + c;
        dofs.push_back(block.displacement[c]);
      }
      for (unsigned int c = 0; c < 3; ++c)
        dofs.push_back(block.multiplier[c]);
      dofs.push_back(system.z);
      block.augmentation = r;
      system.blocks.push_back(block);
      for (const auto i : dofs)
        for (const auto j : dofs)
          dsp.add(i, j);
    }
    dsp.add(system.z, system.z);
    system.pattern.copy_from(dsp);
    system.matrix.reinit(system.pattern);
    system.rhs.reinit(n);

    // Stiffness: diagonally dominant, nonsymmetric, node bandwidth 2.
    for (unsigned int a = 0; a < n_nodes; ++a)
    {
      FullMatrix<double>                   local(6, 6);
      Vector<double>                       local_rhs(6);
      std::vector<types::global_dof_index> dofs;
      const unsigned int                   b = a + 1 < n_nodes ? a + 1 : a - 1;
      for (const unsigned int node : {a, b})
        for (unsigned int c = 0; c < 3; ++c)
          dofs.push_back(3 * node + c);
      for (unsigned int i = 0; i < 6; ++i)
      {
        local_rhs(i) = pseudo_random(a, i);
        for (unsigned int j = 0; j < 6; ++j)
          local(i, j)
            = (i == j ? 400. : 0.) + 60. * pseudo_random(a + i, 7 * j);
      }
      constraints.distribute_local_to_global(local,
                                             local_rhs,
                                             dofs,
                                             system.matrix,
                                             system.rhs);
    }

    // Pairs as ContactCoupling::assemble: rows [u (-P), F_sup, z (a.P)].
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      const TestPair &pair = pairs[p];
      const auto      law_result
        = law.evaluate(pair.multiplier, pair.gap, pair.normal, r);
      // dgap/du: the identity and a curvature-like term; dgap/dz = -a for
      // the force-controlled tool (it moves along a).
      Tensor<2, 3> dgap_du;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          dgap_du[i][j]
            = (i == j ? 1. : 0.) + 0.05 * pseudo_random(p, 3 * i + j);
      const Tensor<1, 3> dgap_dz
        = pair.force_controlled ? Tensor<1, 3>(-axis) : Tensor<1, 3>();
      const Tensor<2, 3> dP_du = law_result.dforce_dgap * dgap_du;
      const Tensor<2, 3> dF_du = law_result.dconstraint_dgap * dgap_du;
      const Tensor<1, 3> dP_dz = law_result.dforce_dgap * dgap_dz;
      const Tensor<1, 3> dF_dz = law_result.dconstraint_dgap * dgap_dz;
      FullMatrix<double> local(7, 7);
      Vector<double>     local_rhs(7);
      for (unsigned int i = 0; i < 3; ++i)
      {
        local_rhs(i)     = law_result.force[i];
        local_rhs(3 + i) = -law_result.constraint_residual[i];
        for (unsigned int j = 0; j < 3; ++j)
        {
          local(i, j)         = -dP_du[i][j];
          local(i, 3 + j)     = -law_result.dforce_dmultiplier[i][j];
          local(3 + i, j)     = dF_du[i][j];
          local(3 + i, 3 + j) = law_result.dconstraint_dmultiplier[i][j];
        }
        local(i, 6)     = -dP_dz[i];
        local(3 + i, 6) = dF_dz[i];
        if (pair.force_controlled)
        {
          for (unsigned int j = 0; j < 3; ++j)
          {
            local(6, j) += axis[i] * dP_du[i][j];
            local(6, 3 + j) += axis[i] * law_result.dforce_dmultiplier[i][j];
          }
          local(6, 6) += axis[i] * dP_dz[i];
        }
      }
      if (pair.force_controlled)
        local_rhs(6) = 10. - axis * law_result.force;
      std::vector<types::global_dof_index> dofs;
      for (unsigned int c = 0; c < 3; ++c)
        dofs.push_back(system.blocks[p].displacement[c]);
      for (unsigned int c = 0; c < 3; ++c)
        dofs.push_back(system.blocks[p].multiplier[c]);
      dofs.push_back(system.z);
      constraints.distribute_local_to_global(local,
                                             local_rhs,
                                             dofs,
                                             system.matrix,
                                             system.rhs);
    }
  }

  double
  relative_residual(const TestSystem &system, const Vector<double> &x)
  {
    Vector<double> residual(system.rhs.size());
    system.matrix.vmult(residual, x);
    residual -= system.rhs;
    return residual.l2_norm() / system.rhs.l2_norm();
  }

  double
  relative_difference(const Vector<double> &a, const Vector<double> &b)
  {
    Vector<double> difference(a);
    difference -= b;
    return difference.linfty_norm() / b.linfty_norm();
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const bool node_on_both_tools : {false, true})
  {
    std::cout << (node_on_both_tools ? "node 7 touches both tools"
                                     : "every node touches one tool at most")
              << std::endl;
    TestSystem system;
    assemble(make_pairs(node_on_both_tools), system);

    solver::LinearSolverParameters whole_parameters;
    whole_parameters.condense_multipliers = false;
    solver::LinearSolver whole_solver(whole_parameters);
    Vector<double>       whole_solution;
    whole_solver.solve(system.matrix, system.rhs, whole_solution, {system.z});
    check_true("the whole solve satisfies the system to 1e-14",
               relative_residual(system, whole_solution) < 1e-14);

    solver::LinearSolverParameters parameters;
    solver::LinearSolver           condensing_solver(parameters);
    condensing_solver.set_multiplier_blocks(system.pattern,
                                            n_u,
                                            system.blocks,
                                            {system.z},
                                            system.constrained);
    Vector<double> solution;
    condensing_solver.solve(system.matrix, system.rhs, solution, {system.z});
    const auto statistics = condensing_solver.statistics();
    check_true("condensed solve used ("
                 + std::to_string(node_on_both_tools ? 0 : 1) + " expected)",
               statistics.condensed_solves == (node_on_both_tools ? 0u : 1u));
    if (!node_on_both_tools)
      check_true("factorised unknowns: the 42 displacements",
                 statistics.factorized_unknowns == n_u);
    check_close("relative difference to the whole solution",
                relative_difference(solution, whole_solution),
                0.,
                1e-13);
    check_close("relative residual of the whole system",
                relative_residual(system, solution),
                0.,
                1e-13);
  }
  return summary();
}
