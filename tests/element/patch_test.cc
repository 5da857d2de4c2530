// Patch test (doc/decisions.md D8) on a distorted mesh: an affine displacement
// u = t A X prescribed on all six faces of the unit cube must be reproduced
// exactly at every interior node, with the same Cauchy stress in every cell,
// for every element technology.
//
// Why it must hold exactly: with u affine, every element sees the same
// H = grad_{x_t} du in every increment (x_t is an affine image of X), so the
// same stress history; P uniform gives interior nodal forces
// P . sum_cells int grad N_a = 0 (2x2x2 Gauss integrates grad N_a exactly on a
// trilinear hexahedron). The SRI correction (tr H_centre - tr H)/3 vanishes
// for uniform H, and its contribution to the residual of an interior node,
// tr P / 3 sum_cells (V_e gbar_a - int grad N_a), vanishes when gbar_a is the
// volume-averaged gradient (Hughes' mean dilatation): on a distorted (warped)
// hexahedron the gradient at the centre differs from that average, and the
// patch test then fails at the level of the distortion. The incompatible
// modes pass because their gradients (j0 / j) J0^{-T} xi_m e_m integrate to
// zero over any cell (Taylor's correction): r_alpha = P : int G~ dV = 0 at
// alpha = 0.
//
// Then a rigid rotation: the stressed, distorted patch turned by 90 degrees
// in ten increments must carry its stress along, sigma -> R sigma R^T.
//
// Two cases: an elastic one (|A| = 1e-4), also compared with small-strain
// Hooke's law, and a plastic one with 10 % strains and a rotation, where the
// SRI and full stresses must coincide too (the SRI correction is zero); the
// plastic one with Hill'48 and with Yld2004-18p (AA2090-T3, Prager).
#include "contact/forming_test_tools.h"
#include "material/material_test_tools.h"
#include "test_utilities.h"

#include <array>
#include <deal.II/base/mpi.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/problem/forming_problem.h>
#include <sstream>

using namespace dealii;
using namespace deepdraw;

namespace
{
  // Cauchy stress averaged over each cell's quadrature points.
  std::vector<Tensor<2, 3>>
  cell_average_cauchy_stress(const problem::FormingProblem &forming_problem)
  {
    const auto               &access  = forming_problem.access();
    const auto               &history = access.state().history;
    std::vector<Tensor<2, 3>> stress(
      access.sheet().triangulation().n_active_cells());
    const unsigned int n_points = history.size() / stress.size();
    for (unsigned int cell = 0; cell < stress.size(); ++cell)
      for (unsigned int q = 0; q < n_points; ++q)
        stress[cell]
          += fe::cauchy_stress(history[cell * n_points + q]) / double(n_points);
    return stress;
  }

  // "t*(A X)_i" for u_x, u_y, u_z.
  std::array<std::string, 3>
  affine_displacement(const Tensor<2, 3> &A)
  {
    std::array<std::string, 3> u;
    for (unsigned int i = 0; i < 3; ++i)
    {
      std::ostringstream expression;
      expression.precision(17);
      expression << "t*(" << A[i][0] << "*x + " << A[i][1] << "*y + " << A[i][2]
                 << "*z)";
      u[i] = expression.str();
    }
    return u;
  }

  // The displacement u prescribed on all six faces of the unit cube.
  // material: entries of subsection Material ("" = the defaults).
  std::string
  prm_text(const std::array<std::string, 3> &u,
           const std::string                &integration,
           const double                      increment,
           const double                      final_load = 1.,
           const std::string                &material   = "")
  {
    const char *faces[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
    const char *components[3] = {"ux", "uy", "uz"};
    std::ostringstream bc;
    for (const char *face : faces)
      for (unsigned int i = 0; i < 3; ++i)
        bc << face << ": " << components[i] << " = " << u[i] << "; ";
    std::string conditions = bc.str();
    conditions.erase(conditions.size() - 2);

    return "subsection Geometry\n"
           "  set Length = 1\n  set Width = 1\n  set Thickness = 1\n"
           "  set Elements along x = 4\n  set Elements along y = 4\n"
           "  set Layers through thickness = 4\n  set Symmetry planes =\n"
           "  set Mesh distortion = 0.25\nend\n"
           "subsection Material\n"
           + material
           + "end\n"
             "subsection Finite element\n  set Element = "
           + integration
           + "\nend\n"
             "subsection Boundary conditions\n"
             "  set Prescribed displacements = "
           + conditions
           + "\nend\n"
             "subsection Process\n  set Final load = "
           + std::to_string(final_load)
           + "\nend\n"
             "subsection Load stepping\n"
             "  set Initial increment = "
           + std::to_string(increment)
           + "\n  set Maximum increment = " + std::to_string(increment)
           + "\nend\n"
             // Converge to round-off: the test measures the discrete
             // solution, not the Newton tolerance.
             "subsection Newton\n  set Force tolerance = 1e-12\n"
             "  set Correction tolerance = 1e-12\nend\n"
             "subsection Output\n  set Output directory = patch-test-output\n"
             "  set Write VTU = false\nend\n";
  }

  struct Result
  {
    std::vector<Tensor<2, 3>> stress;
    double                    min_plastic_strain;
    double                    max_plastic_strain;
  };

  Result
  run_patch_test(const Tensor<2, 3> &A,
                 const std::string  &integration,
                 const double        increment,
                 const std::string  &material = "")
  {
    std::cout << integration << " integration, |A| = " << A.norm() << std::endl;
    const auto forming_problem = forming_test::run_from_text(
      prm_text(affine_displacement(A), integration, increment, 1., material),
      "patch-test-output");

    // Nodal displacements against u = A X at the final load t = 1.
    const auto  &X     = forming_problem->access().sheet().initial_vertices();
    const auto  &u     = forming_problem->access().state().total_displacement;
    double       error = 0., scale = 0.;
    unsigned int n_interior = 0, n_distorted = 0;
    forming_test::for_each_vertex(
      *forming_problem,
      [&](const auto &cell, const unsigned int v, const unsigned int vertex)
      {
        const Tensor<1, 3> expected = A * X[vertex];
        scale                       = std::max(scale, expected.norm());
        bool interior               = true;
        for (unsigned int d = 0; d < 3; ++d)
          interior &= X[vertex][d] > 1e-12 && X[vertex][d] < 1. - 1e-12;
        if (!interior)
          return;
        ++n_interior;
        // Vertices of the regular mesh lie on multiples of 1/4.
        for (unsigned int d = 0; d < 3; ++d)
          if (std::abs(4. * X[vertex][d] - std::round(4. * X[vertex][d]))
              > 1e-3)
          {
            ++n_distorted;
            break;
          }
        for (unsigned int c = 0; c < 3; ++c)
          error
            = std::max(error,
                       std::abs(u[cell->vertex_dof_index(v, c)] - expected[c]));
      });
    deepdraw_test::check_true("27 interior nodes, all moved by the distortion",
                              n_interior == 27 && n_distorted == 27);
    // Round-off of a Newton solution converged to 1e-12.
    deepdraw_test::check_close("max interior |u - A X| / max |A X|",
                               error / scale,
                               0.,
                               1e-10);

    Result result;
    result.stress       = cell_average_cauchy_stress(*forming_problem);
    double stress_error = 0.;
    for (const Tensor<2, 3> &sigma : result.stress)
      stress_error = std::max(stress_error, (sigma - result.stress[0]).norm());
    deepdraw_test::check_close("max |sigma_cell - sigma_cell0| / |sigma_cell0|",
                               stress_error / result.stress[0].norm(),
                               0.,
                               1e-10);
    result.min_plastic_strain = std::numeric_limits<double>::max();
    result.max_plastic_strain = 0.;
    for (const auto &point : forming_problem->access().state().history)
    {
      result.min_plastic_strain
        = std::min(result.min_plastic_strain,
                   point.state.equivalent_plastic_strain);
      result.max_plastic_strain
        = std::max(result.max_plastic_strain,
                   point.state.equivalent_plastic_strain);
    }
    return result;
  }

  // Cell-average Cauchy stresses after stretching the cube by 1e-3 along x
  // (t <= 0.5) and then turning it rigidly by 90 degrees about z in ten
  // increments (t = 0.5 ... 1), or after the stretch only.
  std::vector<Tensor<2, 3>>
  stretch_and_turn(const std::string &integration, const double final_load)
  {
    const std::string stretch = "(1 + 1e-3*(t<0.5 ? 2*t : 1))";
    const std::string angle   = "(t<0.5 ? 0 : (t-0.5)*3.14159265358979324)";
    const std::array<std::string, 3> u
      = {{stretch + "*x*cos" + angle + " - y*sin" + angle + " - x",
          stretch + "*x*sin" + angle + " + y*cos" + angle + " - y",
          "0"}};
    return cell_average_cauchy_stress(
      *forming_test::run_from_text(prm_text(u, integration, 0.05, final_load),
                                   "patch-test-output"));
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // Elastic: |A| ~ 1e-4, well below the yield strain of the default
  // aluminium (C eps0^n / E = 132 / 71000 = 1.9e-3).
  Tensor<2, 3> A_elastic;
  const double entries_elastic[3][3]
    = {{1.0, 0.4, -0.2}, {0.3, -0.5, 0.6}, {-0.1, 0.2, 0.8}};
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      A_elastic[i][j] = 1e-4 * entries_elastic[i][j];

  // Hooke's law for eps = sym A; the finite-strain (Jaumann, updated
  // Lagrangian) answer differs by O(|A|) = 1e-4 relative.
  const double       E = 71000., nu = 0.33;
  const double       lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
  const double       mu     = E / (2. * (1. + nu));
  const Tensor<2, 3> eps    = 0.5 * (A_elastic + transpose(A_elastic));
  const Tensor<2, 3> hooke
    = lambda * trace(eps) * Tensor<2, 3>(unit_symmetric_tensor<3>())
      + 2. * mu * eps;

  for (const std::string integration :
       {"incompatible modes", "selective reduced", "full"})
  {
    const Result result = run_patch_test(A_elastic, integration, 0.5);
    deepdraw_test::check_close("elastic: max epbar",
                               result.max_plastic_strain,
                               0.,
                               0.);
    deepdraw_test::check_close("elastic: |sigma - Hooke| / |Hooke|",
                               (result.stress[0] - hooke).norm() / hooke.norm(),
                               0.,
                               1e-3);
  }

  // Plastic: strains of 5 to 15 % with a rotation part, in four increments.
  Tensor<2, 3> A_plastic;
  const double entries_plastic[3][3]
    = {{0.15, 0.08, -0.03}, {-0.04, -0.06, 0.05}, {0.02, -0.05, -0.07}};
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      A_plastic[i][j] = entries_plastic[i][j];
  // Hill'48 (the default), then Yld2004-18p with the AA2090-T3
  // coefficients (the general return mapping and its tangent in the
  // element) and Prager kinematic hardening.
  const std::string yld2004
    = material_test::yld2004_prm_entries(material_test::aa2090_t3_parameters())
      + "  set Prager modulus = 2000\n";
  for (const std::string material : {std::string(), yld2004})
  {
    const std::string         label = material.empty() ? "" : "Yld2004, ";
    std::vector<Tensor<2, 3>> stress_by_integration;
    for (const std::string integration :
         {"full", "selective reduced", "incompatible modes"})
    {
      const Result result
        = run_patch_test(A_plastic, integration, 0.25, material);
      deepdraw_test::check_true("plastic: " + label
                                  + "every point yielded (min epbar "
                                  + std::to_string(result.min_plastic_strain)
                                  + ")",
                                result.min_plastic_strain > 0.01);
      stress_by_integration.push_back(result.stress[0]);
    }
    // Uniform H: the SRI correction vanishes and the enhanced parameters
    // stay zero (constant stress gives no enhanced force), so every element
    // computes the same material point history.
    deepdraw_test::check_close(
      "plastic: " + label + "|sigma_SRI - sigma_full| / |sigma_full|",
      (stress_by_integration[1] - stress_by_integration[0]).norm()
        / stress_by_integration[0].norm(),
      0.,
      1e-10);
    deepdraw_test::check_close(
      "plastic: " + label + "|sigma_modes - sigma_full| / |sigma_full|",
      (stress_by_integration[2] - stress_by_integration[0]).norm()
        / stress_by_integration[0].norm(),
      0.,
      1e-10);
  }

  // Rigid rotation of a stressed, distorted patch: the Hughes-Winget
  // rotation of a rigid increment is the increment's rotation exactly (the
  // Cayley transform of its own inverse), so the stress turns with the
  // body to round-off, sigma(1) = R sigma(0.5) R^T, R = 90 degrees about z.
  Tensor<2, 3> R;
  R[0][1] = -1.;
  R[1][0] = 1.;
  R[2][2] = 1.;
  for (const std::string integration :
       {"incompatible modes", "selective reduced", "full"})
  {
    std::cout << integration << ": stretch, then a rigid turn" << std::endl;
    const std::vector<Tensor<2, 3>> stretched
      = stretch_and_turn(integration, 0.5);
    const std::vector<Tensor<2, 3>> turned = stretch_and_turn(integration, 1.);
    double                          error  = 0.;
    for (unsigned int cell = 0; cell < turned.size(); ++cell)
      error
        = std::max(error,
                   (turned[cell] - R * stretched[cell] * transpose(R)).norm()
                     / stretched[cell].norm());
    deepdraw_test::check_close(
      "max |sigma(1) - R sigma(0.5) R^T| / |sigma(0.5)|",
      error,
      0.,
      1e-9);
  }
  return deepdraw_test::summary();
}
