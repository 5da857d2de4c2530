// Pure bending of a plane-strain strip at finite strain, and its elastic
// release (doc/theory.md §9.3, D191): the closed form the springback tests
// compare with, to second order in kappa t.
//
// Loaded (Hill, The Mathematical Theory of Plasticity, 1950, ch. VII):
// plane sections stay plane and radial, so the fibre at reference height Z
// from the mid-plane, at the radius r(Z), has the hoop stretch lambda_x =
// r / rho; r_m = r(0) = 1 / kappa (the curvature a test measures) and rho
// follows from a zero axial force, int sigma dr = 0. In plane strain the
// fibres' spacing is their thickness stretch, dr/dZ = lambda_z, taken from
// the fibre's own path (the elastic volume change kept: -nu / (1 - nu) of
// the hoop strain while elastic, 1 / lambda_x once fully plastic; D194).
// The zero-strain fibre is then not the mid-plane: the outer fibres thin,
// the inner ones thicken, and the Cauchy stresses act on those
// thicknesses. The curved fibres need a radial stress, d(r sigma_r)/dr =
// sigma_theta with sigma_r = 0 on both faces (-1.5 MPa at the mid-plane of
// the test's strip, kappa t / 2 of the fibre stress), which shifts each
// fibre's stress by d sigma_xx / d sigma_zz times sigma_r (nu / (1 - nu)
// while elastic, about 1 once plastic: the material's tangent along the
// fibre's path), solved with the zero axial force by a fixed point (D194).
// Released: an elastic curved bar of the loaded section unloaded by -M
// (Winkler: the strain increment k (r - r_n) / r, r_n = t' / ln(r_o / r_i)
// for zero axial force), plane strain modulus E' = E / (1 - nu^2).
// A section may carry an axial force N (a test's held ends react along
// their axis, D196): the zero-strain fibre then follows from int sigma dr =
// N / b, M is taken about the section's centroid, and the release also
// takes off a uniform -N / (b t'). (The radial stress then ends at N / (b
// r_o) on the outer face, not 0: 2e-3 MPa for the test's 0.08 N, left out.)
// With a through-thickness rule (heights Z and weights), the axial force
// and the moment are that rule's sums instead of the integrals: the closed
// form of a section integrated as an element integrates it, which leaves
// the element's own errors apart from its rule's (D196).
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
                  const double            plane_strain_modulus,
                  const double            section_force              = 0.,
                  const std::vector<std::pair<double, double>> &rule = {})
        : fibre(fibre)
        , thickness(thickness)
        , r_m(1. / kappa)
        , axial_force_target(section_force / width)
        , rule(rule)
    {
      radial.assign(n_radial + 1, 0.);
      radii.assign(n_radial + 1, r_m);
      for (unsigned int pass = 0; pass < 6; ++pass)
      {
        // Bisection on the axial force: more rho, shorter fibres.
        double low = 0.98 * r_m, high = 1.02 * r_m;
        for (unsigned int i = 0; i < 200; ++i)
        {
          rho = 0.5 * (low + high);
          map_fibres();
          (axial_force() > axial_force_target ? low : high) = rho;
        }
        // d(r sigma_r)/dr = sigma_theta, sigma_r(r_i) = 0: r sigma_r =
        // int sigma_theta lambda_z dZ from the inner face.
        std::vector<double> next(n_radial + 1, 0.);
        double              integral = 0.;
        for (unsigned int i = 1; i <= n_radial; ++i)
        {
          const double Z0 = height(i - 1), Z1 = height(i);
          integral
            += 0.5 * step()
               * (stress(Z0) * stretch_z(Z0) + stress(Z1) * stretch_z(Z1));
          next[i] = integral / radius(Z1);
        }
        radial = next;
      }
      r_inner          = radius(-thickness / 2.);
      r_outer          = radius(thickness / 2.);
      const double t   = r_outer - r_inner;
      r_neutral        = t / std::log(r_outer / r_inner);
      const double r_c = 0.5 * (r_inner + r_outer);
      // M = int sigma (r - r_c) dr about the section's centroid (about any
      // point when the axial force is zero).
      moment
        = width
          * integrate([this, r_c](double Z)
                      { return stress(Z) * (radius(Z) - r_c) * stretch_z(Z); });
      // Winkler: int E' k (r - r_n) / r (r - r_c) dr = -M / b; the axial
      // force falls off as a uniform -N / (b t).
      unloading_per_radius = -moment / (width * t * (r_c - r_neutral));
      unloading_axial      = -axial_force_target / t;
      // The mid fibre's curvature after release: its rotation per reference
      // length grows by k, its stretch by k (r_m - r_n) / r_m.
      const double k = unloading_per_radius / plane_strain_modulus;
      springback     = -kappa * k * r_neutral / r_m;
    }

    // The radius of the fibre Z: dr/dZ = lambda_z, its thickness stretch.
    double
    radius(const double Z) const
    {
      return interpolate(radii, Z);
    }

    // The loaded Cauchy stress sigma_xx of the fibre Z.
    double
    stress(const double Z) const
    {
      const double eps = std::log(radius(Z) / rho);
      return fibre.stress(eps) + fibre.coupling(eps) * radial_stress(Z);
    }

    // lambda_z of the fibre Z.
    double
    stretch_z(const double Z) const
    {
      return stretch_at(radius(Z));
    }

    double
    radial_stress(const double Z) const
    {
      return interpolate(radial, Z);
    }

    // sigma_xx of the fibre Z after the release.
    double
    residual_stress(const double Z) const
    {
      const double r = radius(Z);
      return stress(Z) + unloading_axial
             + unloading_per_radius * (r - r_neutral) / r;
    }

    double moment;     // N mm
    double springback; // kappa loaded - kappa released, 1 / mm

  private:
    // int f dZ over the thickness, or the rule's sum.
    template <typename Function>
    double
    integrate(const Function &f) const
    {
      if (rule.empty())
        return through_thickness(thickness, f);
      double sum = 0.;
      for (const auto &[Z, weight] : rule)
        sum += weight * f(Z);
      return sum;
    }

    // int sigma dr = int sigma lambda_z dZ.
    double
    axial_force() const
    {
      return integrate([this](double Z) { return stress(Z) * stretch_z(Z); });
    }

    // lambda_z of the fibre at the radius r: the plane-strain fibre's
    // thickness strain at its hoop strain ln(r / rho) (the elastic volume
    // change kept: 1 / lambda_x only once plastic).
    double
    stretch_at(const double r) const
    {
      return std::exp(fibre.thickness_strain(std::log(r / rho)));
    }

    // The radii of the grid's fibres for the current rho: dr/dZ = lambda_z
    // from r(0) = r_m outwards and inwards (Heun's rule).
    void
    map_fibres()
    {
      const unsigned int middle = n_radial / 2;
      radii[middle]             = r_m;
      for (const int direction : {1, -1})
        for (unsigned int i = middle; direction > 0 ? i < n_radial : i > 0;
             i += direction)
        {
          const double h       = direction * step();
          const double k1      = stretch_at(radii[i]);
          const double k2      = stretch_at(radii[i] + h * k1);
          radii[i + direction] = radii[i] + 0.5 * h * (k1 + k2);
        }
    }

    double
    step() const
    {
      return thickness / n_radial;
    }

    double
    height(const unsigned int i) const
    {
      return -thickness / 2. + i * step();
    }

    // A grid table at the height Z, linear between its entries.
    double
    interpolate(const std::vector<double> &values, const double Z) const
    {
      const double s = (Z / thickness + 0.5) * n_radial;
      const auto   k = std::min<unsigned int>(std::max(s, 0.), n_radial - 1);
      return values[k] + (s - k) * (values[k + 1] - values[k]);
    }

    const PlaneStrainFibre       &fibre;
    double                        thickness, r_m, axial_force_target, rho = 0.;
    double                        r_inner = 0., r_outer = 0., r_neutral = 0.;
    double                        unloading_per_radius = 0.; // E' k, MPa
    double                        unloading_axial      = 0.; // MPa
    static constexpr unsigned int n_radial             = 4000;
    std::vector<double>           radial, radii;
    std::vector<std::pair<double, double>> rule;
  };
} // namespace bending_reference

#endif
