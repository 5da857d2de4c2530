// Volumetric locking under isochoric plastic flow (doc/theory.md §3): plane
// strain pure bending of an elastic-perfectly plastic von Mises beam,
// incompatible modes and selective reduced (SRI) against full 2x2x2
// integration.
//
// Why this case: a homogeneous field cannot show locking (the patch test
// holds for both integrations), so the flow must vary through the element.
// In bending, eps_xx = kappa (z - z_n) varies linearly through the layer and
// plastic incompressibility asks eps_zz = -eps_xx, which the trilinear uz
// (d uz / dz linear in x, not in z) cannot follow at all 4 Gauss points of
// the x-z plane: full integration locks; SRI only enforces the cell average.
// Unlike a cantilever (shear-moment interaction, slip-line field at the
// clamp), pure bending has an exact limit load: the uniform fully plastic
// stress field sigma_xx = +-2/sqrt(3) sigma_y (plane strain, von Mises) is
// statically admissible and a uniform-curvature mechanism is kinematically
// admissible, so M_p = 2/sqrt(3) sigma_y b h^2 / 4 exactly.
//
// Set-up: L = 2, b = 0.25 (one element, uy = 0 on both faces: plane
// strain), h = 1; 8 x 1 x 4 cells (square in x-z); xmin clamped
// (ux = uz = 0), xmax rotated as a plane, ux = theta t (z - h/2), uz free:
// a uniform moment M = sum over the xmax nodes of f_x (z - z_mean), measured
// on the current positions. sigma_y = 50 MPa (Swift exponent 0), E = 70 GPa,
// nu = 0.3: the plane-strain yield curvature is kappa_e = 2 eps_e / h with
// eps_e = 2/sqrt(3) sigma_y (1 - nu^2) / E = 7.5e-4; theta = 0.06 gives
// kappa = theta / L = 20 kappa_e at t = 1, where the elastic core is
// 1/20 of h (M / M_p = 1 - (kappa_e / kappa)^2 / 3 = 0.9992 in the
// continuum; all Gauss points are plastic).
//
// Expected SRI error: the trilinear element cannot represent
// uz = -kappa x^2 / 2, leaving the parasitic shear gamma = kappa (x - x_c),
// |gamma| = kappa dx / (2 sqrt 3) at the Gauss points (shear locking, which
// SRI does not address). In the plastic dissipation
// sigma_0 sqrt(eps_xx^2 + gamma^2 / 4) summed over the 8 Gauss points through
// h this is +1.8 % on M for dx = h / 4 and +0.5 % for dx = h / 8
// (parasitic_shear_factor below); the tolerance, 0.5 %, covers the elastic
// core and the rotation of the end face.
//
// Measured (deal.II 9.4, Release, 3 s in all):
//   SRI,  8 x 4 cells: M / M_p = 1.0201 (t = 0.5), 1.0194 (t = 1);
//                      estimate 1.0180
//   SRI, 16 x 4 cells: M / M_p = 1.0079 (t = 1); estimate 1.0047
//   full, 8 x 4 cells: M / M_p = 1.38 (t = 0.5), 1.74 (t = 1): locked, 35 %
//                      then 70 % over the limit load and rising linearly
//                      with the curvature.
//   incompatible modes, 8 x 4 cells: M / M_p = 0.9974 (t = 0.5), 0.9955
//                      (t = 1); 16 x 4: 0.9973, 0.9955. The modes give the
//                      x^2 part of uz (no parasitic shear) and the volumetric
//                      freedom of isochoric flow, without a mean dilatation:
//                      within 0.4 % of the continuum value 0.9992, 2 x 4 x 9
//                      enhanced parameters against 8 incompressibility
//                      conditions per cell leave no locking.
#include "test_utilities.h"

#include <deal.II/base/mpi.h>
#include <deepdraw/problem/forming_problem.h>
#include <iomanip>

using namespace dealii;
using namespace deepdraw;

namespace
{
  const double length = 2., width = 0.25, height = 1., yield_stress = 50.;
  const double theta = 0.06; // end rotation at t = 1

  const unsigned int layers = 4;

  std::string
  prm_text(const std::string &integration,
           const double       final_load,
           const unsigned int elements_along_x)
  {
    return "subsection Geometry\n"
           "  set Length = 2\n  set Width = 0.25\n  set Thickness = 1\n"
           "  set Elements along x = "
           + std::to_string(elements_along_x)
           + "\n  set Elements along y = 1\n"
             "  set Layers through thickness = 4\n  set Symmetry planes =\n"
             "end\n"
             "subsection Material\n"
             "  set Young's modulus = 70000\n  set Poisson's ratio = 0.3\n"
             "  set Hill F = 0.5\n  set Hill G = 0.5\n  set Hill H = 0.5\n"
             "  set Hill L = 1.5\n  set Hill M = 1.5\n  set Hill N = 1.5\n"
             "  set Swift coefficient = 50\n  set Swift prestrain = 0.01\n"
             "  set Swift exponent = 0\nend\n"
             "subsection Finite element\n  set Element = "
           + integration
           + "\nend\n"
             "subsection Boundary conditions\n"
             "  set Prescribed displacements = ymin: uy = 0; ymax: uy = 0; "
             "xmin: ux = 0; xmin: uz = 0; xmax: ux = 0.06*t*(z - 0.5)\nend\n"
             "subsection Process\n  set Final load = "
           + std::to_string(final_load)
           + "\nend\n"
             "subsection Load stepping\n  set Initial increment = 0.05\n"
             "  set Maximum increment = 0.05\nend\n"
             "subsection Output\n  set Output directory = locking-test-output\n"
             "  set Write VTU = false\nend\n";
  }

  // Estimate of M / M_p from the parasitic shear of the
  // trilinear element: sum over the Gauss points through the thickness of
  // |z| sqrt(1 + (gamma / 2 eps_xx)^2) / sum |z|, z measured from mid-height,
  // gamma / 2 = kappa dx / (4 sqrt 3), eps_xx = kappa z.
  double
  parasitic_shear_factor(const unsigned int elements_along_x)
  {
    const double dx = length / elements_along_x, dz = height / layers;
    const double half_gamma = dx / (4. * std::sqrt(3.));
    double       sum = 0., sum_with_shear = 0.;
    for (unsigned int layer = 0; layer < layers; ++layer)
      for (const double s : {-1., 1.})
      {
        const double z = std::abs((layer + 0.5 + s * 0.5 / std::sqrt(3.)) * dz
                                  - 0.5 * height);
        sum += z;
        sum_with_shear += std::sqrt(z * z + half_gamma * half_gamma);
      }
    return sum_with_shear / sum;
  }

  // Bending moment on the xmax face after loading to final_load.
  double
  end_moment(const std::string &integration,
             const double       final_load,
             const unsigned int elements_along_x)
  {
    ParameterHandler prm;
    problem::FormingProblem::declare_parameters(prm);
    prm.parse_input_from_string(
      prm_text(integration, final_load, elements_along_x));
    problem::FormingProblem forming_problem(prm);
    forming_problem.run();

    const auto       &X = forming_problem.access().sheet().initial_vertices();
    const auto       &u = forming_problem.access().state().total_displacement;
    const auto       &f = forming_problem.access().internal_force();
    std::vector<bool> seen(X.size(), false);
    std::vector<std::pair<double, double>> force_and_z; // (f_x, z)
    for (const auto &cell :
         forming_problem.access().sheet().dof_handler().active_cell_iterators())
      for (const unsigned int face : cell->face_indices())
        if (cell->face(face)->at_boundary()
            && cell->face(face)->boundary_id() == 1)
          for (const unsigned int v : cell->face(face)->vertex_indices())
          {
            const unsigned int vertex = cell->face(face)->vertex_index(v);
            if (seen[vertex])
              continue;
            seen[vertex]     = true;
            const auto dof_x = cell->face(face)->vertex_dof_index(v, 0);
            const auto dof_z = cell->face(face)->vertex_dof_index(v, 2);
            force_and_z.emplace_back(f[dof_x], X[vertex][2] + u[dof_z]);
          }
    double z_mean = 0.;
    for (const auto &[fx, z] : force_and_z)
      z_mean += z / force_and_z.size();
    double moment = 0.;
    for (const auto &[fx, z] : force_and_z)
      moment += fx * (z - z_mean);
    std::cout.precision(6); // run() leaves it at 3
    return moment;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     plastic_moment
    = 2. / std::sqrt(3.) * yield_stress * width * height * height / 4.;
  std::cout << std::setprecision(5) << "M_p = " << plastic_moment
            << " N mm, end rotation " << theta << " rad at t = 1" << std::endl;

  // [SRI, full][t = 0.5, t = 1] on 8 x 4 cells; SRI at t = 1 on 16 x 4.
  double            ratio[2][2];
  const std::string integrations[2] = {"selective reduced", "full"};
  for (unsigned int i = 0; i < 2; ++i)
    for (unsigned int k = 0; k < 2; ++k)
    {
      const double t = 0.5 * (k + 1);
      ratio[i][k]    = end_moment(integrations[i], t, 8) / plastic_moment;
      std::cout << integrations[i] << ", 8 x 4 cells, t = " << t
                << ": M / M_p = " << ratio[i][k] << std::endl;
    }
  const double ratio_fine
    = end_moment("selective reduced", 1., 16) / plastic_moment;
  std::cout << "selective reduced, 16 x 4 cells, t = 1: M / M_p = "
            << ratio_fine << std::endl;

  // SRI: the limit load times the parasitic-shear factor (1.018 on 8 x 4,
  // 1.005 on 16 x 4); 0.5 % covers the elastic core (0.1 %) and the
  // rotation of the end face (theta^2 / 2 = 0.2 %).
  deepdraw_test::check_close("SRI M / M_p at t = 0.5, 8 x 4",
                             ratio[0][0],
                             parasitic_shear_factor(8),
                             0.005);
  deepdraw_test::check_close("SRI M / M_p at t = 1, 8 x 4",
                             ratio[0][1],
                             parasitic_shear_factor(8),
                             0.005);
  deepdraw_test::check_close("SRI M / M_p at t = 1, 16 x 4",
                             ratio_fine,
                             parasitic_shear_factor(16),
                             0.005);
  // ... and flat: a limit load, not a hardening response.
  deepdraw_test::check_close("SRI change of M / M_p from t = 0.5 to 1",
                             ratio[0][1] - ratio[0][0],
                             0.,
                             0.005);
  // Incompatible modes: the limit load, the elastic core (1 - 0.9992) and
  // the end rotation (theta^2 / 2 = 0.2 %) within 0.6 %, mesh-independent.
  for (const unsigned int elements_along_x : {8u, 16u})
    for (const double t : {0.5, 1.})
    {
      const double modes = end_moment("incompatible modes", t, elements_along_x)
                           / plastic_moment;
      std::cout << "incompatible modes, " << elements_along_x
                << " x 4 cells, t = " << t << ": M / M_p = " << modes
                << std::endl;
      deepdraw_test::check_close("incompatible modes M / M_p, "
                                   + std::to_string(elements_along_x)
                                   + " x 4, t = " + std::to_string(t),
                                 modes,
                                 1. - std::pow(1. / 20., 2) / 3.,
                                 0.006);
    }
  // Full integration: locked, well above the limit and still rising.
  deepdraw_test::check_true("full integration M / M_p > 1.3 at t = 0.5",
                            ratio[1][0] > 1.3);
  deepdraw_test::check_true("full integration still rising (+20 % of M_p "
                            "from t = 0.5 to 1)",
                            ratio[1][1] - ratio[1][0] > 0.2);
  return deepdraw_test::summary();
}
