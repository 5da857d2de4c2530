// Assembly cost of the reference blank (doc/results.md: 25 x 25 x 2 hexahedra,
// 75 x 75 x 0.81 mm, NUMISHEET'93 aluminium) in a plastic state: residual
// and tangent of IncrementSolver::assemble_system for a displacement
// increment of ~1 % strain (biaxial stretching, thinning, shear, a rotation
// and a non-affine bending part), in microseconds per cell, with one thread
// and with all threads. Target (issue): <= 25 us per cell on 2 cores.
//
//   bench_problem_assembly [repetitions]   (default 40)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/problem/forming_problem.h>

using namespace dealii;
using namespace deepdraw;

namespace
{
  double
  seconds_per_assembly(problem::FormingProblem &forming_problem,
                       const Vector<double>    &du,
                       const unsigned int       repetitions)
  {
    forming_problem.increment_solver().assemble_system(
      du); // warm-up (caches, thread pool)
    const auto start = std::chrono::steady_clock::now();
    for (unsigned int r = 0; r < repetitions; ++r)
      if (!forming_problem.increment_solver().assemble_system(du))
      {
        std::printf("assembly failed\n");
        std::exit(1);
      }
    return std::chrono::duration<double>(std::chrono::steady_clock::now()
                                         - start)
             .count()
           / repetitions;
  }
} // namespace

int
main(int argc, char *argv[])
{
  // No thread limit here: it is set below.
  Utilities::MPI::MPI_InitFinalize mpi(argc,
                                       argv,
                                       numbers::invalid_unsigned_int);
  const unsigned int repetitions = argc > 1 ? std::atoi(argv[1]) : 40;

  // All defaults: the reference blank and material.
  ParameterHandler prm;
  problem::FormingProblem::declare_parameters(prm);
  prm.parse_input_from_string("subsection Output\n"
                              "  set Output directory = bench-assembly\n"
                              "  set Write VTU = false\nend\n");
  problem::FormingProblem forming_problem(prm);
  const DoFHandler<3>    &dof_handler
    = forming_problem.access().sheet().dof_handler();
  const unsigned int n_cells = dof_handler.get_triangulation().n_active_cells();

  // du = A X + bending, A: 1 % biaxial stretch, -1.6 % thinning, shear and
  // a rotation; the yield strain is 132 / 71000 = 0.19 %.
  const double A[3][3]
    = {{0.010, 0.004, 0.}, {-0.002, 0.008, 0.003}, {0., -0.003, -0.016}};
  Vector<double> du(dof_handler.n_dofs());
  for (const auto &cell : dof_handler.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
    {
      const Point<3> &X = cell->vertex(v);
      for (unsigned int c = 0; c < 3; ++c)
      {
        double value = 0.;
        for (unsigned int d = 0; d < 3; ++d)
          value += A[c][d] * X[d];
        du[cell->vertex_dof_index(v, c)] = value;
      }
      du[cell->vertex_dof_index(v, 2)]
        += 0.2 * std::sin(M_PI * X[0] / 75.) * std::sin(M_PI * X[1] / 75.);
    }

  // With the oneTBB back end deal.II fixes the TBB worker limit at the first
  // call of set_thread_limit (in MPI_InitFinalize above); a limit of 1
  // afterwards makes WorkStream run serially. So: all threads first, then 1.
  const unsigned int all_threads = MultithreadInfo::n_cores();
  MultithreadInfo::set_thread_limit(all_threads);
  const double t_all = seconds_per_assembly(forming_problem, du, repetitions);
  MultithreadInfo::set_thread_limit(1);
  const double t_one = seconds_per_assembly(forming_problem, du, repetitions);

  const double plastic_fraction
    = double(forming_problem.increment_solver().progress().plastic_points)
      / (8. * n_cells);
  Vector<double> residual;
  forming_problem.increment_solver().evaluate_residual(du, residual, nullptr);

  std::printf("problem assembly: %u cells, %u dofs, %u repetitions, "
              "plastic points %.1f %%\n",
              n_cells,
              dof_handler.n_dofs(),
              repetitions,
              100. * plastic_fraction);
  std::printf("  1 thread : %8.2f ms per assembly, %6.2f us per cell\n",
              1e3 * t_one,
              1e6 * t_one / n_cells);
  std::printf("  %u threads: %8.2f ms per assembly, %6.2f us per cell "
              "(speed-up %.2f)\n",
              all_threads,
              1e3 * t_all,
              1e6 * t_all / n_cells,
              t_one / t_all);
  std::printf("  |f_int| = %.15e (checksum)\n", residual.l2_norm());
  return 0;
}
