// Barlat's Yld2004-18p yield criterion (Barlat et al., Int. J. Plasticity 21
// (2005) 1009; doc/theory_material.md §1.2): with s the deviator of
// xi = sigma - X in the material axes, S' = C' s, S'' = C'' s and their
// principal values S'_i, S''_j,
//   phi = sum_i sum_j |S'_i - S''_j|^a,   sigma_bar = (phi / phi_0)^(1/a),
// phi_0 = phi of unit uniaxial tension in the rolling direction, so that
// sigma_bar of rolling-direction tension is that stress (the raw formula's
// 4 sigma_bar^a = phi holds for phi_0 = 4, e.g. isotropic coefficients).
// evaluate() gives sigma_bar, its gradient and its Hessian through the
// eigenvalues of S' and S'', exact also for equal eigenvalues (§3.2).
// Immutable after construction; evaluating allocates nothing.
#ifndef deepdraw_material_yld2004_criterion_h
#define deepdraw_material_yld2004_criterion_h

#include <array>
#include <deal.II/base/symmetric_tensor.h>
#include <deepdraw/material/kelvin.h>
#include <deepdraw/material/material_parameters.h>
#include <string>

namespace deepdraw
{
  namespace material
  {
    class Yld2004Criterion
    {
    public:
      // From the coefficients yld2004_c1, yld2004_c2 and the exponent
      // (validated: see degenerate_mode()).
      explicit Yld2004Criterion(const MaterialParameters &parameters);

      double
      equivalent_stress(const dealii::SymmetricTensor<2, 3> &xi) const;

      // sigma_bar of xi (Kelvin coordinates), its gradient d sigma_bar / d xi
      // and, if hessian is not null, d^2 sigma_bar / d xi^2 (both Kelvin).
      // For a hydrostatic xi (sigma_bar = 0) both are set to zero.
      double
      evaluate(const kelvin::Vector &xi,
               kelvin::Vector       &gradient,
               kelvin::Matrix       *hessian) const;

      // phi_0 / 4: how far the raw formula 4 sigma_bar^a = phi is from
      // giving the rolling-direction yield stress (1 when it does).
      double
      raw_rolling_direction_factor() const;

      // "" if every non-zero deviator has a positive sigma_bar with these
      // coefficients (c' and c'' in the order of
      // MaterialParameters::yld2004_c1), otherwise a description of a
      // deviator with sigma_bar = 0.
      static std::string
      degenerate_mode(const std::array<double, 9> &c1,
                      const std::array<double, 9> &c2);

    private:
      double exponent;
      // Kelvin matrices of xi -> S' and xi -> S'' (deviator included).
      kelvin::Matrix transformation[2];
      // phi_0^(1/a).
      double normalisation;

      // phi^(1/a) (sigma_bar before the normalisation), with its gradient
      // and Hessian where the pointers are not null (the Hessian needs the
      // gradient).
      double
      evaluate_raw(const kelvin::Vector &xi,
                   kelvin::Vector       *gradient,
                   kelvin::Matrix       *hessian) const;
    };
  } // namespace material
} // namespace deepdraw

#endif
