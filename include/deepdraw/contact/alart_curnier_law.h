// The node-level frictional contact law of doc/theory_contact.md:
// Alart–Curnier's augmented-Lagrangian projection and its generalised
// (semismooth) derivatives, for one sheet node against one rigid tool
// (reference Eq. 12). All vectors are global components; the law knows nothing
// of the mesh.
#ifndef deepdraw_contact_alart_curnier_law_h
#define deepdraw_contact_alart_curnier_law_h

#include <deal.II/base/tensor.h>

namespace deepdraw
{
  namespace contact
  {
    // Which branch of the projection P is active: open (λ̂_N <= 0), stick
    // (|λ̂_T| <= μ λ̂_N) or slip. Frictionless (μ = 0) closed nodes are
    // always `slip`: their tangential force is zero, and P = λ̂_N n is the
    // only branch whose derivative is right in tangential directions.
    enum class ContactState
    {
      open,
      stick,
      slip
    };

    // "open", "stick" or "slip", for output and messages.
    const char *
    to_string(const ContactState state);

    // Everything the law computes at one point (λ, ĝ, n, r).
    struct AlartCurnierResponse
    {
      ContactState state = ContactState::open;

      // λ̂ = λ − r ĝ.
      dealii::Tensor<1, 3> augmented_force;
      // P(λ̂) = P_N n + P_T: the force of the tool on the node, entering the
      // node equilibrium as  f_int − P = f_ext.
      dealii::Tensor<1, 3> force;
      // F_sup = (λ − P(λ̂)) / r, zero at the solution for any r > 0.
      dealii::Tensor<1, 3> constraint_residual;

      // Generalised derivatives at fixed normal (∂/∂λ, ∂/∂ĝ) and the partial
      // derivative with respect to the normal at fixed λ and ĝ (∂/∂n, taken
      // of the formulas as written, i.e. n is not renormalised; contract it
      // with a tangential variation dn, n·dn = 0).
      dealii::Tensor<2, 3> dforce_dmultiplier;
      dealii::Tensor<2, 3> dforce_dgap;
      dealii::Tensor<2, 3> dforce_dnormal;
      dealii::Tensor<2, 3> dconstraint_dmultiplier;
      dealii::Tensor<2, 3> dconstraint_dgap;
      dealii::Tensor<2, 3> dconstraint_dnormal;
    };

    // Coulomb friction with coefficient μ >= 0 in the Alart–Curnier form:
    //   λ̂ = λ − r ĝ,  P_N = max(0, λ̂_N),
    //   P_T = λ̂_T if |λ̂_T| <= μ P_N, else μ P_N λ̂_T/|λ̂_T|.
    // The augmentation r > 0 is passed per call (the forming problem uses
    // one r for all pairs, ContactParameters::augmentation).
    class AlartCurnierLaw
    {
    public:
      explicit AlartCurnierLaw(const double friction_coefficient);

      double
      friction_coefficient() const;

      // λ: contact force of the tool on the node; gap: ĝ = g_N n + g_T;
      // normal: unit tool normal pointing to the sheet; augmentation: r > 0.
      AlartCurnierResponse
      evaluate(const dealii::Tensor<1, 3> &multiplier,
               const dealii::Tensor<1, 3> &gap,
               const dealii::Tensor<1, 3> &normal,
               const double                augmentation) const;

    private:
      double mu;
    };
  } // namespace contact
} // namespace deepdraw

#endif
