// Gap vector ĝ of one node against one rigid tool (doc/theory_contact.md) and
// its derivatives with respect to the node's displacement increment Δu and to
// the position z of a tool translated along a unit axis a (the
// force-controlled blank holder).
#ifndef deepdraw_contact_contact_pair_kinematics_h
#define deepdraw_contact_contact_pair_kinematics_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deepdraw/geometry/projection_result.h>

namespace deepdraw
{
  namespace contact
  {
    // Which terms of dĝ the linearisation keeps.
    //  - frozen_normal: foot point parameters (u, v) and normal n held
    //    fixed: dĝ/dΔu = I, dĝ/dz = −a, dn = 0.
    //  - full: the closest-point parameters follow the node
    //    (H dξ = Gᵀ(dΔu − a dz), H_αβ = x̄_,α·x̄_,β − (x − x̄)·x̄_,αβ) and the
    //    normal turns with them (Weingarten: dn = −x̄_,α (A⁻¹B)_αβ dξ_β):
    //    the exact derivative on curved tools (radii).
    enum class Linearisation
    {
      frozen_normal,
      full
    };

    // With d = Δu − Δx̄_tool (motion of the node relative to the tool in
    // the increment):
    //   g_N = (x − x̄)·n,  g_T = (I − n⊗n) d,  ĝ = g_N n + g_T.
    class ContactPairKinematics
    {
    public:
      // position: x = X_t + Δu; displacement_increment: Δu;
      // closest_point: the tool surface at the foot point of x, in the
      // tool's current position (foot, normal, tangents and second
      // derivatives; zero tangents skip the curvature terms: the frozen
      // normal); tool_translation_increment: Δx̄_tool, the
      // tool's rigid translation since the start of the increment;
      // tool_axis: unit axis a if the tool position z is an unknown (the
      // blank holder: surface and Δx̄_tool both move by a δz), zero
      // otherwise (punch, die), which makes dĝ/dz = 0.
      ContactPairKinematics(
        const dealii::Point<3>           &position,
        const dealii::Tensor<1, 3>       &displacement_increment,
        const geometry::ProjectionResult &closest_point,
        const dealii::Tensor<1, 3>       &tool_translation_increment,
        const dealii::Tensor<1, 3>       &tool_axis = dealii::Tensor<1, 3>(),
        const Linearisation               linearisation = Linearisation::full);

      double
      normal_gap() const;
      const dealii::Tensor<1, 3> &
      tangential_slip() const;
      // ĝ = g_N n + g_T.
      const dealii::Tensor<1, 3> &
      gap() const;
      const dealii::Tensor<1, 3> &
      normal() const;

      // dĝ/dΔu and dĝ/dz.
      const dealii::Tensor<2, 3> &
      dgap_ddisplacement() const;
      const dealii::Tensor<1, 3> &
      dgap_dtool_position() const;
      // dn/dΔu and dn/dz (zero for the frozen normal).
      const dealii::Tensor<2, 3> &
      dnormal_ddisplacement() const;
      const dealii::Tensor<1, 3> &
      dnormal_dtool_position() const;

      // False for frozen_normal, and for `full` where the curvature terms
      // could not be formed (tangents not given, or the node at a centre of
      // curvature, det H ≈ 0): the frozen-normal derivatives are used then.
      bool
      curvature_terms_included() const;

    private:
      double               g_N;
      dealii::Tensor<1, 3> g_T;
      dealii::Tensor<1, 3> g;
      dealii::Tensor<1, 3> n;
      dealii::Tensor<2, 3> dg_ddu;
      dealii::Tensor<1, 3> dg_dz;
      dealii::Tensor<2, 3> dn_ddu;
      dealii::Tensor<1, 3> dn_dz;
      bool                 curvature_included;
    };
  } // namespace contact
} // namespace deepdraw

#endif
