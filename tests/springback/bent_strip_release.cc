// Springback of a strip bent in plane strain and released by a force
// release stage (D150, D151; doc/theory.md §9).
//
// The strip of tests/element/plastic_bending.cc (L = 24 mm, t = 0.81 mm,
// b = 1 mm, one element wide with uy = 0 on both y faces, von Mises, 32
// elements of 0.75 mm along it, 4 layers, incompatible modes): stage 1 'bend'
// (t 0 -> 1) holds xmin (ux = uz = 0) and rotates xmax as a plane to theta;
// stage 2 'release' (t 1 -> 2, 10 increments) releases the end faces' forces as
// loads that fall to zero, held only by the y faces and supports that
// leave no rigid-body mode (and carry nothing once the loads are gone):
// (a) on the xmin face, (b) 18 mm apart along the strip.
//
// (a) Elastic (Swift coefficient 1e6: no yield), rotated to theta = 0.06
//     (surface strain 1e-3): the strip returns to its initial shape up to
//     the discretisation and the second-order path dependence of the
//     hypoelastic update (the loading and the release follow different
//     strain paths): measured
//     9.8e-7 of the largest bent displacement and 4.6e-6 of the largest
//     bent stress (with 8 elements along the strip 1.6e-5 and 4.5e-5), not
//     the Newton tolerance (1e-10). Asserted: 3e-6 and 1.5e-5.
// (b) Elastoplastic (the default Swift law), theta = 0.6, with 4 layers
//     (the case) and with 8, against the closed form of finite
//     plane-strain bending and its elastic release
//     (springback/finite_bending.h: plane radial sections, a zero axial
//     force, the zero-strain fibre off the mid-plane, the fibres' elastic
//     volume change and the radial stress that holds the curved fibres
//     (Hill 1950, ch. VII); Winkler's curved bar for the release; D191,
//     D194). Measured with 4 (8) layers and asserted, as fractions of the
//     largest value:
//     - the loaded stress at the Gauss points of a middle cell: 1.5 %
//       (1.1 %), asserted 2.5 % (2 %); the largest errors are at the points
//       nearest the mid-plane (2.7 and 1.9 MPa);
//     - the springback Delta kappa against the closed form: -0.95 %
//       (+0.16 %), asserted 2 % (1 %); the 4 layers' -0.95 % is the
//       through-thickness rule's: the closed-form stresses integrated with
//       2 Gauss points per layer give a moment 0.94 % low, and the
//       springback meets that moment's to 1.1e-4 (2.4e-4), asserted 2e-4
//       (5e-4);
//     - the stress each point lost against -E' Delta kappa z of the
//       springback measured: 0.72 % (0.73 %), asserted 2 %;
//     - the residual stress: 4.0 % of its largest value, 63 MPa (2.25 % of
//       104 MPa), asserted 6 % (3.5 %); with the release of the rule's
//       moment 3.7 % (2.2 %), asserted 6 % (3.5 %). The 2 % is not
//       met (D194).
//     32 elements along the strip: with 8 (3 mm cells, aspect 15) the
//     loaded state carried spurious sigma_zz and sigma_xz of 3 to 5 MPa and
//     the residual error was 6.5 %.
// The Newton residuals of the release increments are printed (newton.csv).
#include "contact/forming_test_tools.h"
#include "element/plane_strain_fibre.h"
#include "element/strip_sections.h"
#include "springback/finite_bending.h"
#include "test_utilities.h"

#include <deal.II/base/mpi.h>
#include <deepdraw/fe/quadrature_point_update.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

using namespace dealii;
using namespace deepdraw;

namespace
{
  const double length = 24., width = 1., thickness = 0.81;

  const std::string von_mises = "set Hill F = 0.5\nset Hill G = 0.5\n"
                                "set Hill H = 0.5\nset Hill L = 1.5\n"
                                "set Hill M = 1.5\nset Hill N = 1.5\n";
  const std::string elastic   = von_mises + "set Swift coefficient = 1e6\n";

  // Supports on the xmin face, which the bending does not move: the
  // released strip can go back to where it was.
  const std::string at_the_held_end
    = "point(0, 0, 0): ux uz; point(0, 0, 0.81): ux";
  // Supports 18 mm apart: the node nearest to (18, 0, -3) is on the bent
  // strip (it curls towards -z). Two ux supports 0.81 mm apart let a
  // residual of 3e-5 turn the whole strip (with 8 elements along it the
  // release increments then took a fifth iteration); with these, 4 (0.096,
  // 6.0e-6, 5.4e-8, 3.3e-14) and 5 in the first (0.37 ... 3.6e-14).
  const std::string spread = "point(0, 0, 0): ux uz; point(18, 0, -3): uz";

  // The prm of the strip; with supports, the release stage 2.
  std::string
  strip(const std::string &material,
        const double       theta,
        const std::string &supports,
        const std::string &output,
        const unsigned int layers = 4)
  {
    std::ostringstream prm;
    prm << "subsection Geometry\n  set Length = " << length
        << "\n  set Width = " << width << "\n  set Thickness = " << thickness
        << "\n  set Elements along x = 32\n  set Elements along y = 1\n"
           "  set Layers through thickness = "
        << layers
        << "\n  set Symmetry planes =\n"
           "end\nsubsection Material\n"
        << material
        << "end\nsubsection Boundary conditions\n"
           "  set Prescribed displacements = ymin: uy = 0; ymax: uy = 0; "
           "xmin: ux = 0; xmin: uz = 0; xmax: ux = "
        << length << "*(-(" << theta << "*t)^2/6 + (" << theta
        << "*t)^4/120 - (" << theta << "*t)^6/5040) + sin(" << theta
        << "*t)*(z - " << thickness / 2.
        << ")\nend\nsubsection Process\n  set Final load = "
        << (supports.empty() ? 1 : 2) << "\n";
    if (!supports.empty())
      prm << "  subsection Stage 1\n    set Name = bend\n"
             "    set Final load = 1\n  end\n"
             "  subsection Stage 2\n    set Name = release\n"
             "    set Kind = release\n"
             "    set Prescribed displacements = ymin: uy = 0; ymax: uy = 0\n"
             "    set Release supports = "
          << supports << "\n  end\n";
    prm << "end\nsubsection Load stepping\n  set Initial increment = 0.1\n"
           "  set Maximum increment = 0.1\nend\n"
           "subsection Newton\n  set Force tolerance = 1e-10\n"
           "  set Correction tolerance = 1e-10\nend\n"
           "subsection Output\n  set Output directory = "
        << output << "\nend\n";
    return prm.str();
  }

  struct Shape
  {
    double curvature;
    double largest_displacement;
    double largest_stress;
    // sigma_xx along the strip's axis at the middle cell's Gauss points,
    // by the point's initial height above the mid-plane.
    std::map<double, double> axial_stress;
  };

  // The curvature between the sections x0 = 6 and 18 mm (the rotation of
  // the sections over the arc between their mid-points, as
  // element/plastic_bending.cc measures it), and the stresses.
  Shape
  measure(const problem::FormingProblem &problem, const unsigned int layers)
  {
    const auto &access = problem.access();
    const auto &X      = access.sheet().initial_vertices();
    const auto &u      = access.state().total_displacement;
    Shape       shape{0., 0., 0., {}};
    for (unsigned int i = 0; i < u.size(); ++i)
      shape.largest_displacement
        = std::max(shape.largest_displacement, std::abs(u[i]));
    const bending_reference::StripSections sections(problem, thickness);
    shape.curvature = sections.curvature(6., 18.);

    // Stresses: the middle cells (initial x in [12, 15]) in the frame of
    // the section at x0 = 13.5 (its axis: the rotation of the section).
    Point<3>     middle_a, middle_b;
    const double phi = sections.rotation(12., middle_a)
                       + 0.125
                           * (sections.rotation(18., middle_b)
                              - sections.rotation(6., middle_a));
    const Tensor<1, 3> axis({std::cos(phi), 0., -std::sin(phi)});
    const auto        &history = access.state().history;
    const auto        &gauss   = fe::n_weighted_points;
    for (const auto &cell :
         access.sheet().triangulation().active_cell_iterators())
    {
      const Point<3> centre = [&]()
      {
        Point<3> c;
        for (const unsigned int v : cell->vertex_indices())
          c += X[cell->vertex_index(v)] / 8.;
        return c;
      }();
      for (unsigned int q = 0; q < gauss; ++q)
      {
        const Tensor<2, 3> sigma
          = fe::cauchy_stress(history[cell->active_cell_index() * gauss + q]);
        shape.largest_stress = std::max(shape.largest_stress, sigma.norm());
        if (centre[0] > 12. && centre[0] < 15.)
        {
          // Gauss points of QGauss<3>(2): z fastest last (q / 4), at
          // 1/2 -+ 1/(2 sqrt 3) of the layer.
          const double layer = thickness / layers;
          const double z
            = centre[2] - thickness / 2.
              + (q / 4 == 0 ? -1. : 1.) * layer / (2. * std::sqrt(3.));
          shape.axial_stress[std::round(z * 1e6) / 1e6] = axis * (sigma * axis);
        }
      }
    }
    return shape;
  }

  // The Newton residuals of the increments after load `from` (newton.csv).
  void
  print_newton(const std::string &output, const double from)
  {
    std::ifstream file(output + "/newton.csv");
    std::string   line;
    std::getline(file, line);
    std::cout << "newton.csv of the release: " << line << std::endl;
    while (std::getline(file, line))
    {
      std::istringstream row(line);
      std::string        increment, load;
      std::getline(row, increment, ',');
      std::getline(row, load, ',');
      if (std::stod(load) > from + 1e-12)
        std::cout << "  " << line << std::endl;
    }
  }
  // What (b) asserts for a number of layers (module comment): fractions of
  // the largest value, and of 1 for the springback's two ratios.
  struct Tolerances
  {
    double loaded, springback, rule_springback, unloading, residual,
      rule_residual;
  };

  // (b): the loaded stress, the springback, the unloading and the residual
  // stress against the closed form (module comment).
  void
  check_plastic(const Shape                            &before,
                const Shape                            &after,
                const bending_reference::FiniteBending &finite,
                const double                            E_plane,
                const unsigned int                      layers,
                const Tolerances                       &tolerance)
  {
    const double springback = before.curvature - after.curvature;
    // The closed-form stresses integrated with the element's rule: each of
    // the 2 * layers heights carries t / (2 layers) (2 Gauss points a layer).
    double rule_moment = 0., loaded_error = 0., largest_loaded = 0.;
    for (const auto &[z, stress] : before.axial_stress)
    {
      rule_moment += width * thickness / (2. * layers) * finite.stress(z) * z;
      largest_loaded = std::max(largest_loaded, std::abs(finite.stress(z)));
      loaded_error
        = std::max(loaded_error, std::abs(stress - finite.stress(z)));
    }
    const double rule = rule_moment / finite.moment;
    std::cout << std::setprecision(6) << "plastic, " << layers
              << " layers: kappa bent " << before.curvature << ", released "
              << after.curvature << " / mm; springback " << springback
              << ", closed form " << finite.springback << " (M "
              << finite.moment << " N mm), error "
              << springback / finite.springback - 1. << "; the rule's moment "
              << rule - 1. << " of M; radial stress at the mid-plane "
              << finite.radial_stress(0.) << " MPa" << std::endl;

    double change_error = 0., largest_change = 0.;
    double residual_error = 0., rule_error = 0., largest_residual = 0.;
    for (const auto &[z, stress] : after.axial_stress)
    {
      const double loaded = before.axial_stress.at(z);
      const double change = -E_plane * springback * z;
      const double unload = finite.residual_stress(z) - finite.stress(z);
      largest_change      = std::max(largest_change, std::abs(change));
      change_error = std::max(change_error, std::abs(stress - loaded - change));
      largest_residual
        = std::max(largest_residual, std::abs(finite.residual_stress(z)));
      residual_error = std::max(residual_error,
                                std::abs(stress - finite.residual_stress(z)));
      rule_error
        = std::max(rule_error,
                   std::abs(stress - finite.stress(z) - rule * unload));
      std::cout << "  z " << z << ": loaded " << loaded << " (closed form "
                << finite.stress(z) << "), unloading " << stress - loaded
                << " (-E' dkappa z " << change << "), residual " << stress
                << " (closed form " << finite.residual_stress(z)
                << ", with the rule's moment "
                << finite.stress(z) + rule * unload << ")" << std::endl;
    }
    std::cout << "plastic: largest errors: loaded " << loaded_error
              << " MPa of " << largest_loaded << ", unloading " << change_error
              << " of " << largest_change << ", residual " << residual_error
              << " (with the rule's moment " << rule_error << ") of "
              << largest_residual << std::endl;
    const std::string name = "plastic, " + std::to_string(layers) + " layers: ";
    deepdraw_test::check_true(name + "loaded stress within the tolerance",
                              loaded_error
                                <= tolerance.loaded * largest_loaded);
    deepdraw_test::check_close(name + "springback / closed form",
                               springback / finite.springback,
                               1.,
                               tolerance.springback);
    deepdraw_test::check_close(name + "springback / the rule's closed form",
                               springback / (rule * finite.springback),
                               1.,
                               tolerance.rule_springback);
    deepdraw_test::check_true(name + "unloading stress within the tolerance",
                              change_error
                                <= tolerance.unloading * largest_change);
    deepdraw_test::check_true(name + "residual stress within the tolerance",
                              residual_error
                                <= tolerance.residual * largest_residual);
    deepdraw_test::check_true(name
                                + "residual stress with the rule's "
                                  "moment within the tolerance",
                              rule_error
                                <= tolerance.rule_residual * largest_residual);
  }

  // (b) Elastoplastic: bent, released, and checked against the closed form.
  void
  plastic_strip(const unsigned int layers, const Tolerances &tolerance)
  {
    const std::string bent_output = "plastic-bent-" + std::to_string(layers);
    const std::string released_output
      = "plastic-released-" + std::to_string(layers);
    const auto bent = forming_test::run_from_text(
      strip(von_mises, 0.6, "", bent_output, layers),
      bent_output);
    const Shape before   = measure(*bent, layers);
    const auto  released = forming_test::run_from_text(
      strip(von_mises, 0.6, spread, released_output, layers),
      released_output);
    const Shape after = measure(*released, layers);
    print_newton(released_output, 1.);

    const double                              kappa = before.curvature;
    const bending_reference::PlaneStrainFibre fibre(
      von_mises,
      std::log(1. + kappa * thickness / 2.) * 1.05);
    const double                           E  = fibre.parameters.youngs_modulus;
    const double                           nu = fibre.parameters.poissons_ratio;
    const double                           E_plane = E / (1. - nu * nu);
    const bending_reference::FiniteBending finite(fibre,
                                                  kappa,
                                                  thickness,
                                                  width,
                                                  E_plane);
    check_plastic(before, after, finite, E_plane, layers, tolerance);
  }
} // namespace


int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // (a) Elastic: back to the initial shape.
  {
    const auto bent
      = forming_test::run_from_text(strip(elastic, 0.06, "", "elastic-bent"),
                                    "elastic-bent");
    const Shape before   = measure(*bent, 4);
    const auto  released = forming_test::run_from_text(
      strip(elastic, 0.06, at_the_held_end, "elastic-released"),
      "elastic-released");
    const Shape after = measure(*released, 4);
    print_newton("elastic-released", 1.);
    std::cout << std::setprecision(6) << "elastic: bent kappa "
              << before.curvature << " / mm, largest u "
              << before.largest_displacement << " mm, largest |sigma| "
              << before.largest_stress << " MPa; released: largest u "
              << after.largest_displacement << " mm, largest |sigma| "
              << after.largest_stress << " MPa" << std::endl;
    deepdraw_test::check_true("elastic: every displacement back within "
                              "3e-6 of the largest bent one",
                              after.largest_displacement
                                <= 3e-6 * before.largest_displacement);
    deepdraw_test::check_true("elastic: every stress back within 1.5e-5 of "
                              "the largest bent one",
                              after.largest_stress
                                <= 1.5e-5 * before.largest_stress);
  }

  // (b) Elastoplastic, with the 4 layers and with 8.
  plastic_strip(4, {0.025, 0.02, 2e-4, 0.02, 0.06, 0.06});
  plastic_strip(8, {0.02, 0.01, 5e-4, 0.02, 0.035, 0.035});
  return deepdraw_test::summary();
}
