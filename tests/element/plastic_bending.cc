// Elastoplastic pure bending of a strip in plane strain (doc/theory.md §3):
// no locking, through-thickness integration, Newton order.
//
// Strip L = 24 mm, t = 0.81 mm, b = 1 mm (one element, uy = 0 on both
// sides: plane strain), von Mises with the default Swift law; xmin held
// (ux = uz = 0), xmax rotated as a plane by theta t, uz free, theta = 0.6:
// curvature about 0.025 / mm, surface strain about 1 %, an
// elastic core of about a fifth of the thickness. The xmax face is placed
// where a circular arc of length L ends: ux = L (sin phi / phi - 1) + sin phi
// (z - t/2), phi = theta t (series of sin phi / phi, exact to 1e-10 here);
// holding its centre at x = L instead would stretch the strip by phi^2 / 6.
//
// Pure bending carries the same moment through every section, so the
// moment on the xmax face, M = sum f_x (z - z_c) (current positions), is
// compared at the curvature measured away from the held ends: the rotation
// of the sections x0 = 6 and x0 = 18 mm over the arc between them (the
// held xmin face disturbs about one thickness, all of a first 3 mm
// element: on a 12 mm strip the coarse mesh measured 5 % lower moments).
//
// Reference (independent of the element): M(kappa) = b int sigma_xx z dz,
// with sigma_xx(eps) of the plane-strain fibre (eps_yy = 0, sigma_zz = 0)
// at the logarithmic strain eps = ln(1 + kappa z), integrated along the
// monotonic path in 20 000 steps with the material's return mapping, and
// through the thickness on 4 000 fibres (trapezoidal rule).
//
// Measured (incompatible modes, 2 / 4 / 8 layers):
//   M(3 mm) / M(0.375 mm) = 0.986 / 1.006 / 1.007;
//   |M(3 mm) / M_reference - 1| = 3.2 % / 2.9 % / 1.8 %;
//   last increment: r = 7e-3, 2.9e-5, 9.5e-11, then round-off (1e-13):
//   orders 2.1 and 2.2.
// Asserted:
// - no locking: with 3 mm elements the moment is within 2 % of the moment
//   of 0.375 mm elements with the same layers;
// - the error against the reference falls from 2 to 4 to 8 layers
//   (2 x 2 x 2 Gauss points per layer sample the elastic-plastic stress);
// - Newton converges quadratically in the last, plastic increment:
//   log r_{k+1} / log r_k >= 1.8 over the iterations with r < 1e-2 (with
//   the default enhanced tolerance 1e-4; 1e-12 gives the same iterates to
//   three digits).
// Then Yld2004-18p (AA2090-T3, the general return mapping and its tangent,
// doc/theory_material.md §4), 4 layers: no locking (2 %), the error against
// its own reference (the same fibre integration with that material) within
// 1.5 times the von Mises error with 4 layers, and the Newton order.
// Measured: M(3 mm) / M(0.375 mm) = 1.008, error 3.0 % (von Mises 2.9 %),
// last increment r = 2.4e-2, 8.0e-4, 5.0e-7, 1.5e-12: orders 1.9, 2.0, 1.9.
#include "contact/forming_test_tools.h"
#include "element/plane_strain_fibre.h"
#include "element/strip_sections.h"
#include "material/material_test_tools.h"
#include "test_utilities.h"

#include <deal.II/base/mpi.h>
#include <deepdraw/material/elasto_plasticity.h>
#include <deepdraw/problem/forming_problem.h>
#include <iomanip>
#include <sstream>

using namespace dealii;
using namespace deepdraw;

namespace
{
  const double length = 24., width = 1., thickness = 0.81, theta = 0.6;

  const char *von_mises = "  set Hill F = 0.5\n  set Hill G = 0.5\n"
                          "  set Hill H = 0.5\n  set Hill L = 1.5\n"
                          "  set Hill M = 1.5\n  set Hill N = 1.5\n";

  struct BendingResult
  {
    double              curvature;
    double              moment;
    std::vector<double> last_residuals;
  };

  BendingResult
  bend(const double       element_size,
       const unsigned int layers,
       const std::string &material)
  {
    std::ostringstream prm_text;
    prm_text << "subsection Geometry\n  set Length = " << length
             << "\n  set Width = " << width
             << "\n  set Thickness = " << thickness
             << "\n  set Elements along x = "
             << std::lround(length / element_size)
             << "\n  set Elements along y = 1\n"
                "  set Layers through thickness = "
             << layers
             << "\n  set Symmetry planes =\nend\n"
                "subsection Material\n"
             << material
             << "end\n"
                "subsection Finite element\n  set Element = incompatible "
                "modes\nend\n"
                "subsection Boundary conditions\n"
                "  set Prescribed displacements = ymin: uy = 0; ymax: uy = 0; "
                "xmin: ux = 0; xmin: uz = 0; xmax: ux = "
             << length << "*(-(" << theta << "*t)^2/6 + (" << theta
             << "*t)^4/120 - (" << theta << "*t)^6/5040) + sin(" << theta
             << "*t)*(z - " << thickness / 2.
             << ")\nend\n"
                "subsection Process\n  set Final load = 1\nend\n"
                "subsection Load stepping\n  set Initial increment = 0.1\n"
                "  set Maximum increment = 0.1\nend\n"
                "subsection Newton\n  set Force tolerance = 1e-11\n"
                "  set Correction tolerance = 1e-11\nend\n"
                "subsection Output\n  set Output directory = bending-output\n"
                "  set Write VTU = false\nend\n";
    const auto forming_problem
      = forming_test::run_from_text(prm_text.str(), "bending-output");
    const auto &X = forming_problem->access().sheet().initial_vertices();
    const auto &u = forming_problem->access().state().total_displacement;
    const auto &f = forming_problem->access().internal_force();
    // The end face's nodal forces f_x at their current positions.
    std::vector<std::pair<double, Point<3>>> end_face;
    forming_test::for_each_vertex(
      *forming_problem,
      [&](const auto &cell, const unsigned int v, const unsigned int vertex)
      {
        Point<3> x = X[vertex];
        for (unsigned int c = 0; c < 3; ++c)
          x[c] += u[cell->vertex_dof_index(v, c)];
        if (std::abs(X[vertex][0] - length) < 1e-9)
          end_face.emplace_back(f[cell->vertex_dof_index(v, 0)], x);
      });

    double z_centre = 0., x_centre = 0.;
    for (const auto &[fx, x] : end_face)
    {
      z_centre += x[2] / end_face.size();
      x_centre += x[0] / end_face.size();
    }
    double moment = 0.;
    for (const auto &[fx, x] : end_face)
      moment += fx * (x[2] - z_centre);
    return {bending_reference::StripSections(*forming_problem, thickness)
              .curvature(6., 18.),
            moment,
            forming_problem->increment_solver().progress().force_residuals};
  }


  // b int sigma_xx(ln(1 + kappa z)) z dz over the thickness.
  double
  reference_moment(const double kappa, const std::string &material)
  {
    const double eps_max = std::log(1. + kappa * thickness / 2.) * 1.001;
    return bending_reference::PlaneStrainFibre(material, eps_max)
      .moment(kappa, thickness, width);
  }
  // Lowest log r_k+1 / log r_k over the iterations with r < 1e-2 above the
  // round-off floor (1e-13); checked >= 1.8.
  void
  check_newton_order(const std::vector<double> &r, const std::string &label)
  {
    for (const double value : r)
      std::cout << "  residual " << value << std::endl;
    double       lowest_order = 10.;
    unsigned int n_orders     = 0;
    for (unsigned int k = 0; k + 1 < r.size(); ++k)
      if (r[k] < 1e-2 && r[k + 1] > 1e-12)
      {
        lowest_order
          = std::min(lowest_order, std::log(r[k + 1]) / std::log(r[k]));
        ++n_orders;
      }
    deepdraw_test::check_true(label
                                + "Newton order measured on at least one "
                                  "step",
                              n_orders > 0);
    deepdraw_test::check_true(label + "Newton order log r_k+1 / log r_k = "
                                + std::to_string(lowest_order) + " >= 1.8",
                              lowest_order >= 1.8);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<double>              errors;
  std::vector<std::string>         table;
  for (const unsigned int layers : {2u, 4u, 8u})
  {
    const BendingResult coarse = bend(3., layers, von_mises);
    const BendingResult fine   = bend(0.375, layers, von_mises);
    const double reference     = reference_moment(coarse.curvature, von_mises);
    const double error         = std::abs(coarse.moment / reference - 1.);
    errors.push_back(error);
    std::ostringstream row;
    row << std::setprecision(5) << layers << " layers: kappa "
        << coarse.curvature << " / mm, M(3 mm) " << coarse.moment
        << ", M(0.375 mm) " << fine.moment << " at kappa " << fine.curvature
        << " (reference " << reference_moment(fine.curvature, von_mises)
        << "), reference " << reference << " N mm, error " << error;
    table.push_back(row.str());
    deepdraw_test::check_close("M(3 mm) / M(0.375 mm), "
                                 + std::to_string(layers) + " layers",
                               coarse.moment / fine.moment,
                               1.,
                               0.02);
    // Newton order of the last increment (plastic zone settled).
    if (layers == 2)
      check_newton_order(coarse.last_residuals, "");
  }
  for (const std::string &row : table)
    std::cout << row << std::endl;
  deepdraw_test::check_true("error falls from 2 to 4 to 8 layers",
                            errors[1] < errors[0] && errors[2] < errors[1]);

  // Yld2004-18p (AA2090-T3, bent about the transverse direction): the
  // general return mapping and its tangent in the element, 4 layers.
  {
    const std::string yld2004 = material_test::yld2004_prm_entries(
      material_test::aa2090_t3_parameters());
    const BendingResult coarse    = bend(3., 4, yld2004);
    const BendingResult fine      = bend(0.375, 4, yld2004);
    const double        reference = reference_moment(coarse.curvature, yld2004);
    std::cout << "Yld2004-18p, 4 layers: kappa " << coarse.curvature
              << " / mm, M(3 mm) " << coarse.moment << ", M(0.375 mm) "
              << fine.moment << ", reference " << reference << " N mm"
              << std::endl;
    deepdraw_test::check_close("Yld2004: M(3 mm) / M(0.375 mm)",
                               coarse.moment / fine.moment,
                               1.,
                               0.02);
    deepdraw_test::check_close("Yld2004: |M(3 mm) / M_reference - 1|",
                               std::abs(coarse.moment / reference - 1.),
                               0.,
                               1.5 * errors[1]);
    check_newton_order(coarse.last_residuals, "Yld2004: ");
  }
  return deepdraw_test::summary();
}
