// Pure bending of a plane-strain strip at finite strain, and its elastic
// release (doc/theory.md §9.3, D191): the closed form the springback tests
// compare with, to second order in kappa t.
//
// Loaded (Hill, The Mathematical Theory of Plasticity, 1950, ch. VII):
// plane sections stay plane and radial; the fibres keep their volume
// (lambda_x lambda_z = 1, elastic volume change neglected), so the fibre at
// reference height Z from the mid-plane lies at the radius
// r(Z) = sqrt(r_m^2 + 2 rho Z) with the stretch lambda = r / rho; r_m = 1 /
// kappa is the radius of the fibre Z = 0 (the curvature a test measures) and
// rho follows from a zero axial force, int sigma dr = 0. The zero-strain
// fibre is then not the mid-plane: the outer fibres thin, the inner ones
// thicken, and the Cauchy stresses act on those thicknesses. The curved
// fibres need a radial stress, d(r sigma_r)/dr = sigma_theta with sigma_r
// = 0 on both faces (-1.5 MPa at the mid-plane of the test's strip,
// kappa t / 2 of the fibre stress), which shifts each fibre's stress by
// d sigma_xx / d sigma_zz times sigma_r (nu / (1 - nu) while elastic, about
// 1 once plastic: the material's tangent along the fibre's path), solved
// with the zero axial force by a fixed point (D194).
// Released: an elastic curved bar of the loaded section unloaded by -M
// (Winkler: the strain increment k (r - r_n) / r, r_n = t' / ln(r_o / r_i)
// for zero axial force), plane strain modulus E' = E / (1 - nu^2).
#ifndef deepdraw_tests_springback_finite_bending_h
#define deepdraw_tests_springback_finite_bending_h

#include "element/plane_strain_fibre.h"

#include <cmath>
#include <vector>

namespace bending_reference
{
  class FiniteBending
  {
  public:
    FiniteBending(const PlaneStrainFibre &fibre,
                  const double            kappa,
                  const double            thickness,
                  const double            width,
                  const double            plane_strain_modulus)
        : fibre(fibre)
        , thickness(thickness)
        , r_m(1. / kappa)
    {
      radial.assign(n_radial + 1, 0.);
      for (unsigned int pass = 0; pass < 6; ++pass)
      {
        // Bisection on the axial force: more rho, shorter fibres.
        double low = 0.98 * r_m, high = 1.02 * r_m;
        for (unsigned int i = 0; i < 200; ++i)
        {
          rho                               = 0.5 * (low + high);
          (axial_force() > 0. ? low : high) = rho;
        }
        // d(r sigma_r)/dr = sigma_theta, sigma_r(r_i) = 0: r sigma_r =
        // int sigma_theta rho / r dZ from the inner face.
        std::vector<double> next(n_radial + 1, 0.);
        double              integral = 0.;
        const double        dZ       = thickness / n_radial;
        for (unsigned int i = 1; i <= n_radial; ++i)
        {
          const double Z0 = -thickness / 2. + (i - 1) * dZ, Z1 = Z0 + dZ;
          integral += 0.5 * dZ
                      * (stress(Z0) * rho / radius(Z0)
                         + stress(Z1) * rho / radius(Z1));
          next[i] = integral / radius(Z1);
        }
        radial = next;
      }
      // M = int sigma r dr = rho int sigma dZ (r dr = rho dZ), about the
      // centre; with no axial force about any point.
      moment = width * rho
               * through_thickness(thickness,
                                   [this](double Z) { return stress(Z); });
      r_inner          = radius(-thickness / 2.);
      r_outer          = radius(thickness / 2.);
      const double t   = r_outer - r_inner;
      r_neutral        = t / std::log(r_outer / r_inner);
      const double r_c = 0.5 * (r_inner + r_outer);
      // int E' k (r - r_n) / r  r dr = -M / b.
      unloading_per_radius = -moment / (width * t * (r_c - r_neutral));
      // The mid fibre's curvature after release: its rotation per reference
      // length grows by k, its stretch by k (r_m - r_n) / r_m.
      const double k = unloading_per_radius / plane_strain_modulus;
      springback     = -kappa * k * r_neutral / r_m;
    }

    double
    radius(const double Z) const
    {
      return std::sqrt(r_m * r_m + 2. * rho * Z);
    }

    // The loaded Cauchy stress sigma_xx of the fibre Z.
    double
    stress(const double Z) const
    {
      const double eps = std::log(radius(Z) / rho);
      return fibre.stress(eps) + fibre.coupling(eps) * radial_stress(Z);
    }

    double
    radial_stress(const double Z) const
    {
      const double s = (Z / thickness + 0.5) * n_radial;
      const auto   k = std::min<unsigned int>(std::max(s, 0.), n_radial - 1);
      return radial[k] + (s - k) * (radial[k + 1] - radial[k]);
    }

    // sigma_xx of the fibre Z after the release.
    double
    residual_stress(const double Z) const
    {
      const double r = radius(Z);
      return stress(Z) + unloading_per_radius * (r - r_neutral) / r;
    }

    double moment;     // N mm
    double springback; // kappa loaded - kappa released, 1 / mm

  private:
    // int sigma dr = int sigma / lambda dZ.
    double
    axial_force() const
    {
      return through_thickness(thickness,
                               [this](double Z)
                               { return stress(Z) * rho / radius(Z); });
    }

    const PlaneStrainFibre       &fibre;
    double                        thickness, r_m, rho = 0.;
    double                        r_inner = 0., r_outer = 0., r_neutral = 0.;
    double                        unloading_per_radius = 0.; // E' k, MPa
    static constexpr unsigned int n_radial             = 4000;
    std::vector<double>           radial;
  };
} // namespace bending_reference

#endif
