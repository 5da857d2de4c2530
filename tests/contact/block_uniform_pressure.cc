// Uniform pressure of a block on a flat rigid tool (doc/decisions.md D8, issue
// 4 test 1).
//
// A 2 x 2 x 1 mm block (quarter model, symmetry planes x = 0 and y = 0,
// 4 x 4 x 2 elements) lies on the frictionless plane z = 0
// (data/flat_die.tool); its top face is pushed down by uz = -1e-4 t. With
// no friction the sides and the bottom are free to expand laterally, so the
// exact solution is homogeneous uniaxial stress sigma_zz = -p, which the
// trilinear hexahedra represent exactly. Hence:
//  1. equilibrium: the force of the die on the sheet (sum of the contact
//     forces P) is the opposite of the reaction of the prescribed top face,
//     to the Newton tolerance (1e-12 here): asserted to 1e-8 relative;
//  2. magnitude: p = E eps with eps = 1e-4 (small-strain Hooke's law); the
//     updated-Lagrangian, hypoelastic solution differs by O(eps) terms (log
//     vs engineering strain, lateral growth of the area by 2 nu eps):
//     asserted to 1e-3 relative;
//  3. uniform pressure: the consistent nodal forces of a uniform pressure
//     on bilinear faces are p times the tributary area, h^2 at interior
//     nodes, h^2/2 on the edges of the face, h^2/4 at its corners (ratio
//     1 : 1/2 : 1/4), symmetry edges included; nodal pressure = nodal normal
//     force / tributary area must be the same at all 25 bottom nodes, to
//     1e-8 relative (exact field, converged to 1e-12);
//  4. every bottom node is in contact (status != open), with no friction
//     force and zero gap (|g_N| <= 1e-10 mm, i.e. 1e-6 of the 1e-4 mm
//     compression).
#include "forming_test_tools.h"

#include <deal.II/base/mpi.h>

using namespace dealii;
using namespace deepdraw;
using deepdraw_test::check_close;
using deepdraw_test::check_relative;
using deepdraw_test::check_true;

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const double      E = 71000., strain = 1e-4, side = 2., h = 0.5;
  const std::string text = R"(
subsection Geometry
  set Length                   = 2
  set Width                    = 2
  set Thickness                = 1
  set Elements along x         = 4
  set Elements along y         = 4
  set Layers through thickness = 2
  set Symmetry planes          = x, y
end
subsection Material
  set Young's modulus   = 71000
  set Poisson's ratio   = 0.33
  # Stays elastic: yield stress C eps0^n = 2.3e5 MPa.
  set Swift coefficient = 1e6
end
subsection Boundary conditions
  set Prescribed displacements = zmax: uz = -1e-4*t
end
subsection Process
  set Final load = 1
end
subsection Load stepping
  set Initial increment = 0.5
  set Maximum increment = 0.5
end
subsection Newton
  set Force tolerance      = 1e-12
  set Correction tolerance = 1e-12
end
subsection Contact
  set Friction coefficient = 0
  subsection Tool 1
    set Name          = die
    set File          = flat_die.tool
    set Sheet surface = bottom
  end
end
)";
  const auto        problem
    = forming_test::run_from_text(text, "block_uniform_pressure");

  // 1. Equilibrium of the block: die force + top reaction = 0.
  const Tensor<1, 3> die_force = problem->access().contact().tool_forces()[0];
  const Tensor<1, 3> reaction  = problem->access().face_reaction(5);
  std::cout << "die force " << die_force << ", zmax reaction " << reaction
            << std::endl;
  check_relative("die Fz vs -(zmax reaction)",
                 die_force[2],
                 -reaction[2],
                 1e-8);
  check_close("die Fx, Fy (frictionless)",
              std::abs(die_force[0]) + std::abs(die_force[1]),
              0.,
              1e-8 * die_force[2]);

  // 2. Magnitude against Hooke's law, p = E eps on the area side^2.
  check_relative("die Fz vs E eps A",
                 die_force[2],
                 E * strain * side * side,
                 1e-3);

  // 3. and 4. Nodal pressures on the bottom face.
  const auto nodal = problem->access().contact().nodal_contact(
    problem->access().sheet().initial_vertices().size());
  const auto   bottom = forming_test::vertices_on_plane(*problem, 2, 0.);
  const auto  &X      = problem->access().sheet().initial_vertices();
  const double p_mean = die_force[2] / (side * side);
  double       max_pressure_error = 0., max_gap = 0., max_friction = 0.;
  unsigned int n_active              = 0;
  std::array<unsigned int, 3> n_kind = {{0, 0, 0}};
  for (const unsigned int v : bottom)
  {
    // Tributary area: h^2, halved for each face edge the node lies on.
    unsigned int n_edges = 0;
    for (unsigned int d = 0; d < 2; ++d)
      n_edges
        += (std::abs(X[v][d]) < 1e-10 || std::abs(X[v][d] - side) < 1e-10);
    ++n_kind[n_edges];
    const double area     = h * h / (1 << n_edges);
    const double pressure = nodal[v].normal_force / area;
    max_pressure_error
      = std::max(max_pressure_error, std::abs(pressure - p_mean) / p_mean);
    max_gap      = std::max(max_gap, std::abs(nodal[v].gap));
    max_friction = std::max(max_friction, nodal[v].friction_force.norm());
    n_active += (nodal[v].status != 0);
  }
  std::cout << "mean pressure " << p_mean << " MPa (E eps = " << E * strain
            << ")" << std::endl;
  check_true("25 bottom nodes: 9 interior, 12 edge, 4 corner",
             bottom.size() == 25 && n_kind[0] == 9 && n_kind[1] == 12
               && n_kind[2] == 4);
  check_true("all bottom nodes in contact", n_active == bottom.size());
  check_close("max |p_node - p_mean| / p_mean (tributary 1 : 1/2 : 1/4)",
              max_pressure_error,
              0.,
              1e-8);
  check_close("max |gap| (mm)", max_gap, 0., 1e-10);
  check_close("max |friction force| (N)", max_friction, 0., 1e-8 * p_mean);
  return deepdraw_test::summary();
}
