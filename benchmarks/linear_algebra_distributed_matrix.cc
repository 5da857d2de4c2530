// Which matrix holds the Newton system under mpirun (issue 29, D219): the
// project's row-split deal.II SparseMatrix with its own MUMPS call (D214),
// PETSc's MPI AIJ matrix with MUMPS through PETSc, or Trilinos' Epetra
// matrix with MUMPS through Amesos, on the same system. Not a test.
//
//   mpirun -np R bench_linear_algebra_distributed_matrix ENGINE [N [K]]
//
// ENGINE: deepdraw, petsc or trilinos. An N x N x 2 sheet of hexahedra
// (default N = 100: 20 000 cells, 91 809 unknowns) divided among the ranks
// as a run divides it (METIS, D215), the dofs numbered rank by rank (what
// PETSc and Trilinos need for their contiguous rows), x = 0 held. Each
// rank adds its cells' 24 x 24 matrices (pseudo-random, diagonally
// dominant, as tests/parallel/rows_split_system) through the constraints,
// K times (default 5), and the system is solved twice by MUMPS (analysis
// and factorisation, then again). Rank 0 prints the set-up, the mean
// assembly, each solve, and the solution's norm, which the three engines
// must share. Run each engine as its own process under /usr/bin/time for
// its peak memory.
#include <cmath>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/petsc_solver.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/vector_tools.h>
#include <deepdraw/linear_algebra/newton_linear_system.h>
#include <deepdraw/parallel/cell_partition.h>
#include <deepdraw/parallel/ranks.h>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace dealii;

namespace
{
  constexpr unsigned int n_cell_matrices = 16;

  double
  pseudo_random(const unsigned int k)
  {
    return std::sin(1.3 + 0.71 * k) * std::cos(0.37 * k * k);
  }

  struct Sheet
  {
    explicit Sheet(const unsigned int n)
        : dof_handler(mesh)
    {
      GridGenerator::subdivided_hyper_rectangle(mesh,
                                                {n, n, 2},
                                                Point<3>(0, 0, 0),
                                                Point<3>(n, n, 1),
                                                true);
      deepdraw::parallel::partition_cells(mesh);
      dof_handler.distribute_dofs(FESystem<3>(FE_Q<3>(1), 3));
      DoFRenumbering::subdomain_wise(dof_handler);
      const unsigned int rank = deepdraw::parallel::this_rank();
      owned = DoFTools::locally_owned_dofs_per_subdomain(dof_handler)[rank];
      relevant.set_size(dof_handler.n_dofs());
      std::vector<types::global_dof_index> dofs(24);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (deepdraw::parallel::is_owned(*cell))
        {
          cell->get_dof_indices(dofs);
          relevant.add_indices(dofs.begin(), dofs.end());
        }
      relevant.add_indices(owned);
      VectorTools::interpolate_boundary_values(dof_handler,
                                               0,
                                               Functions::ZeroFunction<3>(3),
                                               constraints);
      constraints.close();
      for (unsigned int m = 0; m < n_cell_matrices; ++m)
      {
        matrices.emplace_back(24, 24);
        rhs.emplace_back(24);
        for (unsigned int i = 0; i < 24; ++i)
        {
          rhs[m](i) = pseudo_random(1000 * m + i);
          for (unsigned int j = 0; j < 24; ++j)
            matrices[m](i, j) = 0.1 * pseudo_random(1000 * m + 50 * i + j);
          matrices[m](i, i) += 5.;
        }
      }
    }

    // Adds each of this rank's cells through the constraints.
    template <typename Add>
    void
    add_cells(const Add &add) const
    {
      std::vector<types::global_dof_index> dofs(24);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (deepdraw::parallel::is_owned(*cell))
        {
          cell->get_dof_indices(dofs);
          const unsigned int m = cell->active_cell_index() % n_cell_matrices;
          add(matrices[m], rhs[m], dofs);
        }
    }

    Triangulation<3>                mesh;
    DoFHandler<3>                   dof_handler;
    AffineConstraints<double>       constraints;
    IndexSet                        owned, relevant;
    std::vector<FullMatrix<double>> matrices;
    std::vector<Vector<double>>     rhs;
  };

  struct Times
  {
    double              set_up = 0., assembly = 0.;
    std::vector<double> solves;
    double              norm = 0.;
  };

  // The time of f() on rank 0's clock, all ranks started together.
  template <typename F>
  double
  timed(const F &f)
  {
    deepdraw::parallel::barrier();
    Timer timer;
    f();
    deepdraw::parallel::barrier();
    return timer.wall_time();
  }

  // The time of `repeats` assemblies into a PETSc or Trilinos matrix and
  // vector through the constraints, off-rank rows sent at compress().
  template <typename Matrix, typename VectorType>
  double
  assembly_time(const Sheet       &sheet,
                Matrix            &matrix,
                VectorType        &rhs,
                const unsigned int repeats)
  {
    double total = 0.;
    for (unsigned int k = 0; k < repeats; ++k)
      total += timed(
        [&]
        {
          matrix = 0.;
          rhs    = 0.;
          sheet.add_cells(
            [&](const FullMatrix<double>                   &local,
                const Vector<double>                       &local_rhs,
                const std::vector<types::global_dof_index> &dofs)
            {
              sheet.constraints.distribute_local_to_global(local,
                                                           local_rhs,
                                                           dofs,
                                                           matrix,
                                                           rhs);
            });
          matrix.compress(VectorOperation::add);
          rhs.compress(VectorOperation::add);
        });
    return total;
  }

  Times
  run_deepdraw(const Sheet &sheet, const unsigned int repeats)
  {
    namespace la = deepdraw::linear_algebra;
    Times                                    times;
    deepdraw::solver::LinearSolverParameters parameters;
    parameters.reuse = deepdraw::solver::LinearSolverParameters::Reuse::never;
    std::unique_ptr<la::NewtonLinearSystem> system;
    la::SystemLayout                        layout;
    layout.dof_handler           = &sheet.dof_handler;
    layout.constraints           = &sheet.constraints;
    layout.n_unknowns            = sheet.dof_handler.n_dofs();
    layout.add_contact_couplings = [](DynamicSparsityPattern &) {};
    times.set_up                 = timed(
      [&]
      {
        system = la::make_system(parameters);
        system->reinit(layout);
      });
    for (unsigned int k = 0; k < repeats; ++k)
      times.assembly += timed(
        [&]
        {
          system->zero(true);
          sheet.add_cells(
            [&](const FullMatrix<double>                   &matrix,
                const Vector<double>                       &rhs,
                const std::vector<types::global_dof_index> &dofs)
            {
              system->matrix().add_local(sheet.constraints,
                                         matrix,
                                         rhs,
                                         dofs,
                                         system->rhs());
            });
          deepdraw::parallel::sum(system->rhs().begin(), system->rhs().size());
          system->matrix().sum_over_ranks();
        });
    Vector<double> solution(layout.n_unknowns);
    for (unsigned int s = 0; s < 2; ++s)
      times.solves.push_back(timed([&] { system->solve(solution, {}, {}); }));
    times.norm = solution.l2_norm();
    return times;
  }

  Times
  run_petsc(const Sheet &sheet, const unsigned int repeats)
  {
    Times                            times;
    PETScWrappers::MPI::SparseMatrix matrix;
    PETScWrappers::MPI::Vector       rhs, solution;
    times.set_up = timed(
      [&]
      {
        DynamicSparsityPattern dsp(sheet.relevant);
        DoFTools::make_sparsity_pattern(sheet.dof_handler,
                                        dsp,
                                        sheet.constraints,
                                        false,
                                        deepdraw::parallel::this_rank());
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   sheet.owned,
                                                   MPI_COMM_WORLD,
                                                   sheet.relevant);
        matrix.reinit(sheet.owned, sheet.owned, dsp, MPI_COMM_WORLD);
        rhs.reinit(sheet.owned, MPI_COMM_WORLD);
        solution.reinit(sheet.owned, MPI_COMM_WORLD);
      });
    times.assembly = assembly_time(sheet, matrix, rhs, repeats);
    for (unsigned int s = 0; s < 2; ++s)
      times.solves.push_back(timed(
        [&]
        {
          SolverControl                    control;
          PETScWrappers::SparseDirectMUMPS mumps(control, MPI_COMM_WORLD);
          mumps.solve(matrix, solution, rhs);
        }));
    times.norm = solution.l2_norm();
    return times;
  }

  Times
  run_trilinos(const Sheet &sheet, const unsigned int repeats)
  {
    Times                          times;
    TrilinosWrappers::SparseMatrix matrix;
    TrilinosWrappers::MPI::Vector  rhs, solution;
    times.set_up = timed(
      [&]
      {
        // Writable rows: a rank adds to rows another owns (step-40's
        // pattern for a distributed assembly).
        TrilinosWrappers::SparsityPattern pattern(sheet.owned,
                                                  sheet.owned,
                                                  sheet.relevant,
                                                  MPI_COMM_WORLD);
        DoFTools::make_sparsity_pattern(sheet.dof_handler,
                                        pattern,
                                        sheet.constraints,
                                        false,
                                        deepdraw::parallel::this_rank());
        pattern.compress();
        matrix.reinit(pattern);
        rhs.reinit(sheet.owned, sheet.relevant, MPI_COMM_WORLD, true);
        solution.reinit(sheet.owned, MPI_COMM_WORLD);
      });
    times.assembly = assembly_time(sheet, matrix, rhs, repeats);
    TrilinosWrappers::MPI::Vector owned_rhs(sheet.owned, MPI_COMM_WORLD);
    owned_rhs = rhs;
    for (unsigned int s = 0; s < 2; ++s)
      times.solves.push_back(timed(
        [&]
        {
          SolverControl                                  control;
          TrilinosWrappers::SolverDirect::AdditionalData data(false,
                                                              "Amesos_Mumps");
          TrilinosWrappers::SolverDirect                 mumps(control, data);
          mumps.solve(matrix, solution, owned_rhs);
        }));
    times.norm = solution.l2_norm();
    return times;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                engine = argc > 1 ? argv[1] : "";
  const unsigned int               n      = argc > 2 ? std::stoi(argv[2]) : 100;
  const unsigned int               repeats = argc > 3 ? std::stoi(argv[3]) : 5;
  if (engine != "deepdraw" && engine != "petsc" && engine != "trilinos")
  {
    std::cerr << "usage: bench_linear_algebra_distributed_matrix "
                 "deepdraw|petsc|trilinos [N [K]]\n";
    return 1;
  }
  const Sheet sheet(n);
  const Times times = engine == "deepdraw" ? run_deepdraw(sheet, repeats)
                      : engine == "petsc"  ? run_petsc(sheet, repeats)
                                           : run_trilinos(sheet, repeats);
  if (deepdraw::parallel::is_root())
    std::cout << std::setprecision(4) << engine << " on "
              << deepdraw::parallel::n_ranks() << " ranks, "
              << sheet.dof_handler.n_dofs() << " unknowns: set-up "
              << times.set_up << " s, assembly " << times.assembly / repeats
              << " s (mean of " << repeats << "), solves " << times.solves[0]
              << " s and " << times.solves[1]
              << " s, |x| = " << std::setprecision(12) << times.norm << '\n';
  return 0;
}
