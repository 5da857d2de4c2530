// The assembled tangent is the exact derivative of the assembled residual
// (doc/theory_material.md): compare it with central finite differences on a
// small distorted mesh, in an elastic and in a plastic state, for every element
// technology, after a few increments with rotation. With incompatible modes
// the residual is the condensed one (enhanced parameters solved in the
// element), so this also checks the static condensation.
#include "test_utilities.h"

#include <deal.II/base/mpi.h>
#include <deepdraw/problem/forming_problem.h>
#include <random>

using namespace dealii;
using namespace deepdraw;

namespace
{
  std::string
  prm_text(const std::string &integration, const double final_load)
  {
    return "subsection Geometry\n"
           "  set Length = 2\n  set Width = 1\n  set Thickness = 0.5\n"
           "  set Elements along x = 2\n  set Elements along y = 1\n"
           "  set Layers through thickness = 2\n  set Symmetry planes = x\n"
           "  set Mesh distortion = 0.2\nend\n"
           "subsection Material\n  set Prager modulus = 1000\nend\n"
           "subsection Finite element\n  set Element = "
           + integration
           // Enhanced parameters solved to round-off: the condensed
           // tangent is then the exact derivative (with the default 1e-6
           // the error of K is of the order of that tolerance: 2e-8 at 1e-6).
           + "\n  set Enhanced tolerance = 1e-13\nend\n"
             "subsection Boundary conditions\n"
             "  set Prescribed displacements = zmin: uz = 0; ymin: uy = 0; "
             "xmax: ux = 0.05*t; xmax: uz = 0.2*t*(x-1)\nend\n"
             "subsection Process\n  set Final load = "
           + std::to_string(final_load)
           + "\nend\n"
             "subsection Load stepping\n  set Initial increment = 0.25\n"
             "  set Maximum increment = 0.25\nend\n"
             "subsection Output\n  set Output directory = tangent-test-output\n"
             "  set Write VTU = false\nend\n";
  }

  void
  check_tangent(const std::string &integration, const double final_load)
  {
    std::cout << integration << " element, after load " << final_load
              << std::endl;
    ParameterHandler prm;
    problem::FormingProblem::declare_parameters(prm);
    prm.parse_input_from_string(prm_text(integration, final_load));
    problem::FormingProblem forming_problem(prm);
    if (final_load > 0.)
      forming_problem.run();

    const unsigned int n
      = forming_problem.access().sheet().dof_handler().n_dofs();
    // A displacement increment that plastifies (strain ~ 2 %) with rotation.
    std::mt19937                           random(42);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    Vector<double>                         du(n);
    for (unsigned int i = 0; i < n; ++i)
      du[i] = 0.01 * uniform(random);

    Vector<double>     residual(n), plus(n), minus(n);
    FullMatrix<double> tangent;
    deepdraw_test::check_true("residual evaluates",
                              forming_problem.increment_solver()
                                .evaluate_residual(du, residual, &tangent));

    const double h         = 1e-7;
    double       max_error = 0., max_entry = 0.;
    for (unsigned int j = 0; j < n; ++j)
    {
      Vector<double> perturbed = du;
      perturbed[j] += h;
      forming_problem.increment_solver().evaluate_residual(perturbed,
                                                           plus,
                                                           nullptr);
      perturbed[j] -= 2 * h;
      forming_problem.increment_solver().evaluate_residual(perturbed,
                                                           minus,
                                                           nullptr);
      for (unsigned int i = 0; i < n; ++i)
      {
        const double fd = (plus[i] - minus[i]) / (2 * h);
        max_error       = std::max(max_error, std::abs(fd - tangent(i, j)));
        max_entry       = std::max(max_entry, std::abs(tangent(i, j)));
      }
    }
    // Central differences with h = 1e-7 on entries ~1e4: measured 4e-11 to
    // 7e-11 for every element (round-off of the residual over 2h); 1e-9
    // fails on any missing tangent term (a wrong term is O(1e-3) or more).
    deepdraw_test::check_close("max |K - K_fd| / max |K|",
                               max_error / max_entry,
                               0.,
                               1e-9);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_tangent("incompatible modes", 0.);
  check_tangent("incompatible modes", 0.5);
  check_tangent("selective reduced", 0.);
  check_tangent("full", 0.);
  check_tangent("selective reduced", 0.5);
  return deepdraw_test::summary();
}
