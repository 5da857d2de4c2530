// Coulomb friction of a pressed block dragged along a flat rigid tool
// (doc/decisions.md D8, issue 4 test 2).
//
// A 2 x 1 x 1 mm block (half model, symmetry plane y = 0, 4 x 2 x 2
// elements) lies on the plane z = 0 (data/flat_die.tool), friction
// mu = 0.162. Load 0 -> 1: the top face is pressed down by 1e-3 mm
// (p = E eps = 71 MPa); load 1 -> 2: the top face is dragged along +x by s
// while uz stays. Poisson's ratio is 0 so that pressing causes no lateral
// expansion, hence no friction force before the drag: the drag then starts
// from lambda_T = 0 everywhere, and below the limit nothing slips.
//
// Slip (s = 0.01 mm, 30 x the elastic shear displacement mu p H / G =
// 3.2e-4 mm needed to reach the limit): every bottom node must slip, where
// the law (doc/theory_contact.md) gives |lambda_T| = mu lambda_N per node; the
// slip direction is +x at every node (nu = 0: no motion along y to first order
// in the strains; the y component of the die force is bounded by eps^2 ~ 1e-6
// of its normal force), so the total
// tangential force of the die is -mu times its normal force: asserted to
// 1e-6 relative per node and in total (Newton converged to 1e-12).
// Equilibrium with the reaction of the dragged face: 1e-8 relative.
//
// Stick (s = 2e-5 mm, tangential force ~ G A s / H = 1.4 N against
// mu N = 23 N): every bottom node must stick (state stick,
// |lambda_T| < mu lambda_N) and not move relative to the fixed die: stick
// enforces g_T = 0 in every increment, so |u_x| of the bottom nodes is
// Newton round-off (~1e-14 mm); asserted below 1e-6 s, far below what any
// slipping node would show (O(s)).
#include "forming_test_tools.h"

#include <deal.II/base/mpi.h>

using namespace dealii;
using namespace deepdraw;
using deepdraw_test::check_close;
using deepdraw_test::check_relative;
using deepdraw_test::check_true;

namespace
{
  const double mu = 0.162;

  std::string
  prm_text(const double drag)
  {
    std::ostringstream text;
    text << R"(
subsection Geometry
  set Length                   = 2
  set Width                    = 1
  set Thickness                = 1
  set Elements along x         = 4
  set Elements along y         = 2
  set Layers through thickness = 2
  set Symmetry planes          = y
end
subsection Material
  set Young's modulus   = 71000
  set Poisson's ratio   = 0
  set Swift coefficient = 1e6
end
subsection Boundary conditions
  set Prescribed displacements = zmax: uz = -1e-3*min(t, 1); zmax: ux = )"
         << drag << R"(*max(t - 1, 0)
end
subsection Process
  set Final load = 2
end
subsection Load stepping
  set Initial increment = 0.25
  set Maximum increment = 0.25
end
subsection Newton
  set Force tolerance      = 1e-12
  set Correction tolerance = 1e-12
  set Maximum iterations   = 25
end
subsection Contact
  set Friction coefficient = 0.162
  subsection Tool 1
    set Name          = die
    set File          = flat_die.tool
    set Sheet surface = bottom
  end
end
)";
    return text.str();
  }

  void
  check_equilibrium(const problem::FormingProblem &problem)
  {
    const Tensor<1, 3> die_force = problem.access().contact().tool_forces()[0];
    const Tensor<1, 3> reaction  = problem.access().face_reaction(5);
    std::cout << "die force " << die_force << ", zmax reaction " << reaction
              << std::endl;
    check_relative("die Fz vs -(zmax reaction)",
                   die_force[2],
                   -reaction[2],
                   1e-8);
    check_close("die Fx vs -(zmax reaction)",
                die_force[0],
                -reaction[0],
                1e-8 * die_force[2]);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  {
    std::cout << "--- slip: drag 0.01 mm" << std::endl;
    const double drag = 0.01;
    const auto   problem
      = forming_test::run_from_text(prm_text(drag), "block_friction_slip");
    check_equilibrium(*problem);
    const Tensor<1, 3> die_force = problem->access().contact().tool_forces()[0];
    check_relative("die Fx vs -mu Fz (slip, +x)",
                   die_force[0],
                   -mu * die_force[2],
                   1e-6);
    // Motion along y (hence a y component of the slip direction) appears only
    // at second order in the strains (eps^2 ~ 1e-6) with nu = 0.
    check_close("die Fy", die_force[1], 0., 1e-6 * die_force[2]);

    const auto nodal = problem->access().contact().nodal_contact(
      problem->access().sheet().initial_vertices().size());
    const auto   bottom    = forming_test::vertices_on_plane(*problem, 2, 0.);
    unsigned int n_slip    = 0;
    double       worst_law = 0., min_ux = drag;
    for (const unsigned int v : bottom)
    {
      n_slip += (nodal[v].status == 2);
      worst_law = std::max(worst_law,
                           std::abs(nodal[v].friction_force.norm()
                                    - mu * nodal[v].normal_force)
                             / (mu * nodal[v].normal_force));
      min_ux
        = std::min(min_ux, forming_test::vertex_displacement(*problem, v)[0]);
    }
    check_true("all 15 bottom nodes slip",
               bottom.size() == 15 && n_slip == bottom.size());
    check_close("max | |lambda_T| - mu lambda_N | / (mu lambda_N) per node",
                worst_law,
                0.,
                1e-6);
    // The block has slid: each bottom node moved by the drag less the
    // elastic shear before slip (~3.2e-4 mm + edge effects).
    check_true("bottom nodes slid along +x by more than s/2",
               min_ux > 0.5 * drag);
  }

  {
    std::cout << "--- stick: drag 2e-5 mm" << std::endl;
    const double drag = 2e-5;
    const auto   problem
      = forming_test::run_from_text(prm_text(drag), "block_friction_stick");
    check_equilibrium(*problem);
    const Tensor<1, 3> die_force = problem->access().contact().tool_forces()[0];
    check_true("die carries a tangential force (block sheared)",
               std::abs(die_force[0]) > 0.1);
    const auto nodal = problem->access().contact().nodal_contact(
      problem->access().sheet().initial_vertices().size());
    const auto   bottom    = forming_test::vertices_on_plane(*problem, 2, 0.);
    unsigned int n_stick   = 0;
    double       max_ratio = 0., max_slip = 0.;
    for (const unsigned int v : bottom)
    {
      n_stick += (nodal[v].status == 1);
      max_ratio            = std::max(max_ratio,
                           nodal[v].friction_force.norm()
                             / (mu * nodal[v].normal_force));
      const Tensor<1, 3> u = forming_test::vertex_displacement(*problem, v);
      max_slip             = std::max(max_slip, std::hypot(u[0], u[1]));
    }
    std::cout << "max |lambda_T| / (mu lambda_N) = " << max_ratio << std::endl;
    check_true("all 15 bottom nodes stick",
               bottom.size() == 15 && n_stick == bottom.size());
    check_true("below the Coulomb limit at every node", max_ratio < 1.);
    check_close("max tangential displacement of the bottom nodes (mm)",
                max_slip,
                0.,
                1e-6 * drag);
  }
  return deepdraw_test::summary();
}
