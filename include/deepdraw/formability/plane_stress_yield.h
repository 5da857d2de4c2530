// The yield function of the sheet in plane stress, as the forming-limit
// analysis needs it (doc/theory_formability.md §3): the equivalent stress of
// an in-plane stress state given in the material axes (1 = rolling,
// 2 = transverse direction) and its gradient. An interface, so that every
// criterion of subsection Material slots into the Marciniak-Kuczynski
// analysis without changing it: HillPlaneStress (Hill'48) and
// Yld2004PlaneStress (Yld2004-18p), chosen by create_plane_stress_yield().
#ifndef deepdraw_formability_plane_stress_yield_h
#define deepdraw_formability_plane_stress_yield_h

#include <deal.II/base/symmetric_tensor.h>
#include <deepdraw/material/material_parameters.h>
#include <deepdraw/material/yld2004_criterion.h>
#include <memory>
#include <string>

namespace deepdraw
{
  namespace formability
  {
    // An in-plane stress or strain (rate) in the material axes.
    using PlaneTensor = dealii::SymmetricTensor<2, 2>;

    class PlaneStressYield
    {
    public:
      virtual ~PlaneStressYield() = default;

      // sigma_bar(s), positively homogeneous of degree one, normalised so
      // that it is the yield stress in uniaxial tension along the rolling
      // direction (the stress the Swift law gives).
      virtual double
      equivalent_stress(const PlaneTensor &stress) const = 0;

      // d sigma_bar / d sigma as a tensor (d sigma_bar = g : d sigma with the
      // full contraction). By normality and plastic-work equivalence the
      // plastic strain rate is epsbar_dot g, so g is also the strain-rate
      // direction per unit equivalent strain. Homogeneous of degree zero.
      virtual PlaneTensor
      gradient(const PlaneTensor &stress) const = 0;
    };


    // Hill'48 in plane stress (sigma_33 = sigma_13 = sigma_23 = 0):
    // sigma_bar^2 = (G+H) s11^2 - 2H s11 s22 + (F+H) s22^2 + 2N s12^2
    // (doc/theory_material.md §1 with the out-of-plane stresses zero).
    class HillPlaneStress : public PlaneStressYield
    {
    public:
      // Uses F, G, H and N; validates the parameters (InputError).
      explicit HillPlaneStress(const material::MaterialParameters &parameters);

      double
      equivalent_stress(const PlaneTensor &stress) const override;

      PlaneTensor
      gradient(const PlaneTensor &stress) const override;

    private:
      double F, G, H, N;
    };


    // Yld2004-18p (material::Yld2004Criterion, doc/theory_material.md §1.2)
    // in plane stress: the 3D criterion at sigma_33 = sigma_13 = sigma_23 =
    // 0, normalised like it to rolling-direction tension. The gradient is
    // the in-plane part of the 3D gradient, which the criterion gives in
    // Kelvin coordinates (shear times sqrt 2): g_12 = n_K,12 / sqrt 2 in the
    // full-contraction convention of PlaneStressYield::gradient
    // (doc/theory_formability.md §3.1).
    class Yld2004PlaneStress : public PlaneStressYield
    {
    public:
      // Validates the parameters (InputError).
      explicit Yld2004PlaneStress(
        const material::MaterialParameters &parameters);

      double
      equivalent_stress(const PlaneTensor &stress) const override;

      PlaneTensor
      gradient(const PlaneTensor &stress) const override;

    private:
      material::Yld2004Criterion criterion;
    };


    // The plane-stress yield function of Material/Yield criterion:
    // HillPlaneStress or Yld2004PlaneStress (validates the parameters).
    std::unique_ptr<PlaneStressYield>
    create_plane_stress_yield(const material::MaterialParameters &parameters);

    // "Hill'48", or "Yld2004-18p a = 8" (the exponent), for descriptions.
    std::string
    plane_stress_yield_name(const material::MaterialParameters &parameters);


    // The strain-rate ratio eps2_dot / eps1_dot of uniaxial tension along
    // the rolling direction (-r0 / (1 + r0) for Hill'48).
    double
    uniaxial_strain_ratio(const PlaneStressYield &yield);

    // The stress state on the unit yield locus (sigma_bar = 1) with
    // principal axes along the material axes, sigma_11 >= 0 the larger
    // component, whose strain-rate ratio eps2_dot / eps1_dot is rho; rho
    // between uniaxial_strain_ratio() and 1. Found by bisection on the
    // direction of the stress in the (s11, s22) plane, where the ratio
    // increases monotonically for a convex yield function.
    PlaneTensor
    stress_for_strain_ratio(const PlaneStressYield &yield, double rho);
  } // namespace formability
} // namespace deepdraw

#endif
