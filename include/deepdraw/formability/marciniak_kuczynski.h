// The Marciniak-Kuczynski (M-K) forming-limit analysis
// (doc/theory_formability.md §4): a sheet with a groove whose initial
// thickness is f0 times that of the rest, strained proportionally outside
// the groove, rigid-plastic, in plane stress, with the program's own yield
// function (any PlaneStressYield: Hill'48 or Yld2004-18p) and the isotropic
// hardening law of subsection Material (MkHardening: Swift, Voce or
// tabulated). The limit strain of a strain path is the strain of
// the homogeneous zone when the groove's equivalent strain increment first
// exceeds the homogeneous zone's by the localisation factor, minimised over
// the initial groove angle on the left side of the diagram.
#ifndef deepdraw_formability_marciniak_kuczynski_h
#define deepdraw_formability_marciniak_kuczynski_h

#include <deepdraw/formability/mk_hardening.h>
#include <deepdraw/formability/plane_stress_yield.h>
#include <deepdraw/material/material_parameters.h>
#include <limits>
#include <vector>

namespace deepdraw
{
  namespace formability
  {
    // Subsection Formability/Marciniak-Kuczynski (doc/user_guide.md §8).
    struct MarciniakKuczynskiParameters
    {
      // f0 = t_groove / t_sheet at the start, 0 < f0 <= 1.
      double imperfection = 0.99;
      // Grid of initial groove angles on the left side, degrees (0, 45];
      // the best grid angle is refined by a golden-section search.
      double groove_angle_step = 2.;
      // Equivalent plastic strain of the groove per step, (0, 0.05].
      double strain_increment = 0.001;
      // Localised when d(epsbar_groove) > factor d(epsbar_sheet), > 1.
      double localisation_factor = 10.;
      // Strain ratios of the curve: the material's uniaxial ratio, then the
      // multiples of this step up to 1, (0, 0.5].
      double strain_ratio_step = 0.1;

      // Throws InputError naming "Formability/Marciniak-Kuczynski/<entry>"
      // and the allowed values.
      void
      validate() const;
    };


    struct MkLimitPoint
    {
      // eps2_dot / eps1_dot of the homogeneous zone; eps1 along the rolling
      // direction.
      double strain_ratio = 0.;
      // Logarithmic strains of the homogeneous zone at localisation.
      double major_strain = 0.;
      double minor_strain = 0.;
      // The critical initial groove angle: between the groove normal and the
      // major strain direction, degrees.
      double groove_angle = 0.;
    };


    class MarciniakKuczynski
    {
    public:
      // Keeps references to yield (which must outlive this object). Throws
      // InputError if the parameters are invalid or the law does not harden
      // (MkHardening::without_hardening: the limit strain is zero).
      MarciniakKuczynski(const PlaneStressYield             &yield,
                         const MkHardening                  &hardening,
                         const MarciniakKuczynskiParameters &parameters);

      // The limit strain of the homogeneous zone for the strain ratio rho
      // and the initial groove angle (degrees). +infinity if the groove does
      // not localise before its equivalent strain reaches 10, or if the
      // major strain of the homogeneous zone passes bound first (a search
      // that has found a lower limit already stops there). InputError if
      // no step converges, naming the saturation of the hardening law
      // where the analysis asked for a stress beyond it (D171).
      MkLimitPoint
      limit_for_groove_angle(double rho,
                             double groove_angle,
                             double bound
                             = std::numeric_limits<double>::infinity()) const;

      // The limit of the strain ratio rho: for rho < 0 the least over the
      // initial groove angles in [0, 45] degrees, else the groove normal to
      // the major strain (and, at rho = 1, to the minor one too). Throws
      // InputError if the groove never localises (f0 = 1).
      MkLimitPoint
      limit_point(double rho) const;

      // The strain ratios of the curve (MarciniakKuczynskiParameters).
      std::vector<double>
      strain_ratios() const;

      // limit_point() of every strain ratio, in the order of strain_ratios().
      std::vector<MkLimitPoint>
      limit_curve() const;

    private:
      // Golden-section search for the least limit within one grid step of
      // the best grid angle.
      MkLimitPoint
      refine_groove_angle(double rho, const MkLimitPoint &grid_best) const;

      const PlaneStressYield      &yield;
      MkHardening                  hardening;
      MarciniakKuczynskiParameters parameters;
    };
  } // namespace formability
} // namespace deepdraw

#endif
