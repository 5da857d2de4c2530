// Input parameters of the contact law, `subsection Contact` of the .prm
// file (ASPECT pattern: the caller enters the subsection).
#ifndef deepdraw_contact_contact_parameters_h
#define deepdraw_contact_contact_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deepdraw/contact/contact_pair_kinematics.h>

namespace deepdraw
{
  namespace contact
  {
    struct ContactParameters
    {
      // Coulomb coefficient μ, on all tools (NUMISHEET'93: 0.162).
      double friction_coefficient = 0.162;
      // r in N/mm; 0 selects the automatic value (one for all pairs).
      double augmentation_parameter = 0;
      // Factor on the automatic r.
      double augmentation_scaling = 1;
      // Derivative of the gap used in the Newton matrix.
      Linearisation linearisation = Linearisation::full;

      // Declares the entries in the current subsection.
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      // Reads them back; throws deepdraw::InputError on a value out of
      // range, naming `Contact/<entry>` and the allowed values.
      void
      parse_parameters(dealii::ParameterHandler &prm);

      // r: the fixed value if given, otherwise scaling × E × h (N/mm), the
      // order of the nodal stiffness of a hexahedron of size h (E in MPa,
      // h in mm), so that r ĝ and λ have the same magnitude. The forming
      // problem calls it once, with h = sqrt(dx dy) of the blank's
      // structured mesh, and gives every pair the same r.
      double
      augmentation(const double youngs_modulus,
                   const double element_size) const;
    };
  } // namespace contact
} // namespace deepdraw

#endif
