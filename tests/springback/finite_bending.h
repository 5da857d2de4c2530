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
// thicken, and the Cauchy stresses act on those thicknesses.
// Released: an elastic curved bar of the loaded section unloaded by -M
// (Winkler: the strain increment k (r - r_n) / r, r_n = t' / ln(r_o / r_i)
// for zero axial force), plane strain modulus E' = E / (1 - nu^2).
#ifndef deepdraw_tests_springback_finite_bending_h
#define deepdraw_tests_springback_finite_bending_h

#include "element/plane_strain_fibre.h"

#include <cmath>

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
      // Bisection on the axial force: more rho, shorter fibres.
      double low = 0.98 * r_m, high = 1.02 * r_m;
      for (unsigned int i = 0; i < 200; ++i)
      {
        rho                               = 0.5 * (low + high);
        (axial_force() > 0. ? low : high) = rho;
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
      return fibre.stress(std::log(radius(Z) / rho));
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

    const PlaneStrainFibre &fibre;
    double                  thickness, r_m, rho = 0.;
    double                  r_inner = 0., r_outer = 0., r_neutral = 0.;
    double                  unloading_per_radius = 0.; // E' k, MPa
  };
} // namespace bending_reference

#endif
