// Parameters of the sheet material (doc/theory_material.md): isotropic
// elasticity, the yield criterion (Hill'48 or Barlat's Yld2004-18p), the
// isotropic hardening law (Swift, Voce or a table) and Prager kinematic
// hardening. Defaults: NUMISHEET'93 aluminium (doc/results.md), Hill'48 and
// Swift. Units: MPa.
#ifndef deepdraw_material_material_parameters_h
#define deepdraw_material_material_parameters_h

#include <array>
#include <deal.II/base/tensor.h>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace deepdraw
{
  namespace material
  {
    enum class YieldCriterion
    {
      hill48,
      yld2004_18p
    };

    enum class HardeningLawType
    {
      swift,
      voce,
      tabulated
    };

    struct MaterialParameters
    {
      double youngs_modulus = 71000.; // E, MPa
      double poissons_ratio = 0.33;   // nu

      // Hill'48 coefficients in the orthotropy frame (1 = rolling,
      // 2 = transverse, 3 = normal); von Mises: F = G = H = 1/2, L = M = N =
      // 3/2.
      double hill_F = 0.5932, hill_G = 0.5848, hill_H = 0.4152;
      double hill_L = 1.272, hill_M = 1.272, hill_N = 1.272;

      YieldCriterion yield_criterion = YieldCriterion::hill48;

      // Yld2004-18p (Barlat et al. 2005), in the paper's order c12 c13 c21
      // c23 c31 c32 c44 c55 c66 with 4 = 23 (yz), 5 = 31 (zx), 6 = 12 (xy):
      // C' (yld2004_c1) and C'' (yld2004_c2), and the exponent a. All 1:
      // Hosford's isotropic criterion (von Mises for a = 2).
      std::array<double, 9> yld2004_c1 = {{1., 1., 1., 1., 1., 1., 1., 1., 1.}};
      std::array<double, 9> yld2004_c2 = {{1., 1., 1., 1., 1., 1., 1., 1., 1.}};
      double                yld2004_exponent = 8.;

      HardeningLawType hardening_law = HardeningLawType::swift;

      // Swift law Y = C (eps0 + epbar)^n, MPa.
      double swift_coefficient = 576.79, swift_prestrain = 0.01658,
             swift_exponent = 0.3593;

      // Voce law Y = A - B exp(-C epbar) (A, B in MPa); defaults: the Voce
      // curve closest to the Swift default on 0 <= epbar <= 0.3.
      double voce_A = 413., voce_B = 280.8, voce_C = 6.5;

      // Tabulated Y(epbar): (epbar, Y) pairs from epbar = 0, strictly
      // increasing strains, non-decreasing stresses, piecewise linear and
      // extrapolated with the last slope; default: the Swift default
      // sampled.
      std::vector<std::pair<double, double>> hardening_table = {{0., 132.2},
                                                                {0.02, 175.7},
                                                                {0.05, 217.9},
                                                                {0.1, 266.5},
                                                                {0.2, 332.9},
                                                                {0.3, 381.5},
                                                                {0.5, 454.9}};

      // Prager linear kinematic hardening dX = k d(eps^p), MPa; 0 = off.
      double prager_modulus = 0.;

      // Angle from the global x axis to the rolling direction (axis 1),
      // counterclockwise about the sheet normal z, in degrees: the initial
      // material axes are R0 = rotation about z by this angle (0: R0 = I,
      // rolling direction = x). Not used by ElastoPlasticity, which works
      // in the material frame; the forming problem sets the history with it.
      double rolling_direction_angle = 0.;

      // Declares the entries inside the *current* subsection (the caller
      // enters "Material").
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      // Reads the entries from the current subsection, then validate().
      void
      parse_parameters(dealii::ParameterHandler &prm);

      // The initial material axes: columns rolling, transverse, normal
      // direction in global coordinates (rotation by
      // rolling_direction_angle about z).
      dealii::Tensor<2, 3>
      initial_material_axes() const;

      // Checks what a Pattern cannot (E > 0, -1 < nu < 1/2, C > 0, eps0 > 0,
      // 0 <= n < 1, F, G, H >= 0 with pairwise sums > 0, L, M, N > 0, the
      // Yld2004-18p coefficients finite with a bounded yield surface, 2 <= a
      // <= 50, the Voce constants and the table). Throws
      // deepdraw::InputError naming the parameter ("Material/Hill G") and
      // the allowed values.
      void
      validate() const;
    };
  } // namespace material
} // namespace deepdraw

#endif
