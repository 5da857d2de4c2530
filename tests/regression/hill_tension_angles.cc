// Uniaxial tension of a Hill'48 + Swift bar at 0, 45 and 90 degrees to the
// rolling direction (NUMISHEET'93 aluminium, the defaults: F = 0.5932,
// G = 0.5848, H = 0.4152, N = 1.272), on a mesh, against the closed form.
//
// Uniaxial stress sigma at the angle theta to the rolling direction (axis
// 1): sigma_11 = sigma c^2, sigma_22 = sigma s^2, sigma_12 = sigma s c, so
// Hill's equivalent stress is k_theta sigma with
//   k_theta^2 = F s^4 + G c^4 + H (c^2 - s^2)^2 + 2 N s^2 c^2
// (G + H at 0, (F + G)/4 + N/2 at 45, F + H at 90 degrees), hence
//   sigma = Y(epbar) / k_theta,  epbar = (e - sigma/E) / k_theta
// (plastic-work equivalence sigma de^p = k sigma depbar) with the
// logarithmic strain e along the bar and Y the Swift law, as in
// tension_bar.check.py. The plastic strain ratio width/thickness is
//   r_0 = H/G = 0.7100,  r_90 = H/F = 0.6999,  r_45 = N/(F + G) - 1/2 = 0.5798.
// Measured on the deformed mesh at the end (e = 0.3, below the Considère
// strain n - k eps0 = 0.34 of every direction, so the bar stays
// homogeneous): width and thickness from the displaced faces ymax/xmax and
// zmax, strains e_w = ln(w/w0), e_t = ln(t/t0); their plastic parts add
// the isotropic elastic contraction nu sigma/E; r = e_w^p / e_t^p.
//
// Cases (one eighth of the bar, symmetry planes x = 0, y = 0, z = 0;
// element `selective reduced`, and `incompatible modes` for 45 degrees;
// the homogeneous field is exact for both; increments of 0.02 in t, i.e.
// 0.006 in strain; Newton tolerances 1e-10):
//  - 0:  Rolling direction angle = 0, pulled along x;
//  - 90: angle 0, pulled along y (ymax: uy), no new parameter involved;
//  - 90 by the angle: Rolling direction angle = 90, pulled along x; must
//    equal the y pull to round-off (the same bar turned by a quarter turn);
//  - 45: Rolling direction angle = 45, pulled along x, with Hill F = G
//    (= 0.5848; r_45 = N/(2G) - 1/2 = 0.5876). With F != G the free
//    uniaxial state shears in the x-y plane ((F - G) sigma/4 per unit
//    plastic flow), which the symmetry planes x = 0 and y = 0 forbid: the
//    quarter model is then no longer homogeneous (with the default F the
//    faces xmax and zmax were found warped by 7e-4 mm, against 1e-12 mm
//    here). F = G (with L = M) makes the material symmetric about the 45
//    degree line, so the symmetry planes are exact and N is what 45
//    degrees tests; F and G are tested apart at 0 and 90 degrees.
// Tolerances, about 3 times the largest error measured over the cases
// (time integration of the hypoelastic law and the additive split of the
// logarithmic strain in the closed form):
//  - force against the closed form at every increment with e >= 0.03, and
//    the final stress F/(w t): 3e-6 relative [7.5e-7 and 1.04e-6];
//  - r against the closed form: 3e-6 relative [7.7e-7 at 45 degrees,
//    5e-7 at 0 and 90];
//  - e_w, e_t against the closed form: 1e-6 absolute [3.5e-7];
//  - every node of the faces xmax (or ymax) and zmax at the same position,
//    to 1e-9 mm [5e-12 mm];
//  - 90 by the angle = 90 by the y pull, and the two elements at 45
//    degrees: 1e-10 relative [force 1.6e-12 and 3.8e-13, r 1e-14].
// Without the rolling direction angle (R0 = I in every case) the 90 and 45
// degree cases would fail: sigma_45 is 5 % above sigma_0 here, r_45 17 %
// below r_0, r_90 1.4 % below r_0.
#include "contact/forming_test_tools.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <sstream>

using namespace dealii;
using namespace deepdraw;
using deepdraw_test::check_close;
using deepdraw_test::check_relative;
using deepdraw_test::check_true;

namespace
{
  const double E = 71000., nu = 0.33;
  const double F = 0.5932, G = 0.5848, H = 0.4152, N = 1.272;
  const double C = 576.79, eps0 = 0.01658, n = 0.3593;
  const double final_strain = 0.3;

  // About 3 times the largest error measured over the cases (see above).
  const double FORCE_TOLERANCE  = 3e-6; // relative; measured 1.04e-6
  const double R_TOLERANCE      = 3e-6; // relative; measured 7.7e-7
  const double STRAIN_TOLERANCE = 1e-6; // absolute; measured 3.5e-7

  double
  hill_factor(const double theta_degrees, const double F)
  {
    const double theta = theta_degrees * numbers::PI / 180.;
    const double c = std::cos(theta), s = std::sin(theta);
    return std::sqrt(F * std::pow(s, 4) + G * std::pow(c, 4)
                     + H * std::pow(c * c - s * s, 2) + 2. * N * s * s * c * c);
  }

  double
  r_value(const double theta_degrees, const double F)
  {
    if (theta_degrees == 0.)
      return H / G;
    if (theta_degrees == 90.)
      return H / F;
    return N / (F + G) - 0.5; // 45 degrees
  }

  // Uniaxial stress at the logarithmic strain e along the bar.
  double
  closed_form_stress(const double e, const double k)
  {
    const double elastic_limit = C * std::pow(eps0, n) / k;
    if (E * e <= elastic_limit)
      return E * e;
    double low = elastic_limit, high = E * e;
    for (unsigned int i = 0; i < 200; ++i)
    {
      const double sigma = 0.5 * (low + high);
      const double epbar = (e - sigma / E) / k;
      (sigma - C * std::pow(eps0 + epbar, n) / k > 0. ? high : low) = sigma;
    }
    return 0.5 * (low + high);
  }

  struct Result
  {
    double force, strain_width, strain_thickness, r;
  };

  // Reads `column` of reactions.csv in `directory`: (load, value) rows.
  std::vector<std::pair<double, double>>
  read_reactions(const std::string &directory, const std::string &column)
  {
    std::ifstream                          file(directory + "/reactions.csv");
    std::string                            line, cell;
    std::vector<std::pair<double, double>> rows;
    std::getline(file, line);
    std::vector<std::string> header;
    std::istringstream       names(line);
    while (std::getline(names, cell, ','))
      header.push_back(cell);
    const auto at = std::find(header.begin(), header.end(), column);
    check_true("reactions.csv has " + column, at != header.end());
    const std::size_t index = at - header.begin();
    while (std::getline(file, line))
    {
      std::vector<double> values;
      std::istringstream  cells(line);
      while (std::getline(cells, cell, ','))
        values.push_back(std::stod(cell));
      if (values.size() == header.size())
        rows.emplace_back(values[0], values[index]);
    }
    return rows;
  }

  // One case: the modelled eighth of the bar, 10 mm along `pull` (0 = x,
  // 1 = y), 1 x 1 mm section; rolling direction at `angle` degrees from x;
  // theta = angle of the pull to the rolling direction.
  Result
  run_case(const std::string &name,
           const unsigned int pull,
           const double       angle,
           const double       theta,
           const std::string &element,
           const double       hill_F = F)
  {
    std::cout << "\n" << name << std::endl;
    const unsigned int width_direction = 1 - pull;
    const double       length = 10., width = 1., thickness = 1.;
    const std::string  pulled_face = pull == 0 ? "xmax" : "ymax";
    const std::string  component   = pull == 0 ? "ux" : "uy";
    std::ostringstream text;
    text << "subsection Geometry\n"
         << "  set Length = " << (pull == 0 ? length : width) << "\n"
         << "  set Width = " << (pull == 0 ? width : length) << "\n"
         << "  set Thickness = " << thickness << "\n"
         << "  set Elements along x = " << (pull == 0 ? 4 : 2) << "\n"
         << "  set Elements along y = " << (pull == 0 ? 2 : 4) << "\n"
         << "  set Layers through thickness = 2\n"
         << "  set Symmetry planes = x, y\n"
         << "end\n"
         << "subsection Finite element\n"
         << "  set Element = " << element << "\n"
         << "end\n"
         << "subsection Material\n"
         << "  set Rolling direction angle = " << angle << "\n"
         << "  set Hill F = " << hill_F << "\n"
         << "end\n"
         << "subsection Boundary conditions\n"
         << "  set Prescribed displacements = zmin: uz = 0; " << pulled_face
         << ": " << component << " = " << length << "*(exp(" << final_strain
         << "*t)-1)\n"
         << "end\n"
         << "subsection Process\n"
         << "  set Final load = 1\n"
         << "end\n"
         << "subsection Load stepping\n"
         << "  set Initial increment = 0.02\n"
         << "  set Maximum increment = 0.02\n"
         << "end\n"
         << "subsection Newton\n"
         << "  set Force tolerance = 1e-10\n"
         << "  set Correction tolerance = 1e-10\n"
         << "end\n";
    const std::string output  = "hill_tension_" + name;
    const auto        problem = forming_test::run_from_text(text.str(), output);
    const double      k       = hill_factor(theta, hill_F);

    // Force at every converged increment (reactions.csv).
    double worst_force = 0.;
    for (const auto &[load, force] :
         read_reactions(output, pulled_face + "_F" + (pull == 0 ? "x" : "y")))
    {
      const double e = final_strain * load;
      if (e < 0.03)
        continue;
      const double sigma = closed_form_stress(e, k);
      const double expected
        = sigma * width * thickness * std::exp(-e + (1. - 2. * nu) * sigma / E);
      worst_force = std::max(worst_force, std::abs(force / expected - 1.));
    }
    check_close(name + ": force vs closed form, all increments (relative)",
                worst_force,
                0.,
                FORCE_TOLERANCE);

    // Width and thickness on the deformed mesh; homogeneity.
    auto face_position = [&](const unsigned int direction, const double X0)
    {
      const auto vertices
        = forming_test::vertices_on_plane(*problem, direction, X0);
      double sum = 0., low = 1e300, high = -1e300;
      for (const unsigned int v : vertices)
      {
        const double x
          = X0 + forming_test::vertex_displacement(*problem, v)[direction];
        sum += x;
        low  = std::min(low, x);
        high = std::max(high, x);
      }
      check_close(name + ": face " + std::to_string(direction)
                    + " stays plane (spread of the node positions, mm)",
                  high - low,
                  0.,
                  1e-9);
      return sum / vertices.size();
    };
    const double w   = face_position(width_direction, width);
    const double t   = face_position(2, thickness);
    const double e_w = std::log(w / width);
    const double e_t = std::log(t / thickness);
    const double force
      = problem->access().face_reaction(pull == 0 ? 1 : 3)[pull];
    const double sigma = force / (w * t);

    const double sigma_expected = closed_form_stress(final_strain, k);
    const double e_p            = final_strain - sigma_expected / E;
    const double r_expected     = r_value(theta, hill_F);
    const double e_w_expected
      = -nu * sigma_expected / E - r_expected / (1. + r_expected) * e_p;
    const double e_t_expected
      = -nu * sigma_expected / E - 1. / (1. + r_expected) * e_p;
    const double r = (e_w + nu * sigma / E) / (e_t + nu * sigma / E);
    std::cout << name << ": sigma " << sigma << " MPa (closed form "
              << sigma_expected << ", k_theta " << k << "), e_w " << e_w
              << ", e_t " << e_t << ", r " << r << " (closed form "
              << r_expected << ")" << std::endl;
    check_relative(name + ": stress F/(w t) vs closed form",
                   sigma,
                   sigma_expected,
                   FORCE_TOLERANCE);
    check_close(name + ": width strain vs closed form",
                e_w,
                e_w_expected,
                STRAIN_TOLERANCE);
    check_close(name + ": thickness strain vs closed form",
                e_t,
                e_t_expected,
                STRAIN_TOLERANCE);
    check_relative(name + ": r-value vs closed form",
                   r,
                   r_expected,
                   R_TOLERANCE);
    return {force, e_w, e_t, r};
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout.precision(10);

  const Result r0  = run_case("0deg", 0, 0., 0., "selective reduced");
  const Result r90 = run_case("90deg_pull_y", 1, 0., 90., "selective reduced");
  const Result r90_angle
    = run_case("90deg_by_angle", 0, 90., 90., "selective reduced");
  const Result r45    = run_case("45deg", 0, 45., 45., "selective reduced", G);
  const Result r45_im = run_case("45deg_incompatible_modes",
                                 0,
                                 45.,
                                 45.,
                                 "incompatible modes",
                                 G);

  std::cout << std::endl;
  check_relative(
    "90 degrees: angle 90 pulled along x = angle 0 along y (force)",
    r90_angle.force,
    r90.force,
    1e-10);
  check_relative("90 degrees: angle 90 pulled along x = angle 0 along y (r)",
                 r90_angle.r,
                 r90.r,
                 1e-10);
  check_relative("45 degrees: incompatible modes = selective reduced (force)",
                 r45_im.force,
                 r45.force,
                 1e-10);
  check_relative("45 degrees: incompatible modes = selective reduced (r)",
                 r45_im.r,
                 r45.r,
                 1e-10);
  // The anisotropy is resolved: the directions differ far beyond the
  // tolerances (closed forms: F_45/F_0 = 1.051, r_45/r_0 = 0.828,
  // r_90/r_0 = 0.986).
  check_true("45 degrees stronger than 0 by > 4 %",
             r45.force > 1.04 * r0.force);
  check_true("r_45 < r_0 by > 15 %", r45.r < 0.85 * r0.r);
  check_true("r_90 < r_0 by > 1 %", r90.r < 0.99 * r0.r);
  return deepdraw_test::summary();
}
