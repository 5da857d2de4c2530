#include <deal.II/base/exceptions.h>
#include <deepdraw/contact/alart_curnier_law.h>

namespace deepdraw
{
  namespace contact
  {
    namespace
    {
      dealii::Tensor<2, 3>
      identity()
      {
        dealii::Tensor<2, 3> I;
        for (unsigned int i = 0; i < 3; ++i)
          I[i][i] = 1.;
        return I;
      }
    } // namespace


    const char *
    to_string(const ContactState state)
    {
      switch (state)
      {
        case ContactState::open:
          return "open";
        case ContactState::stick:
          return "stick";
        case ContactState::slip:
          return "slip";
      }
      return "unknown";
    }


    AlartCurnierLaw::AlartCurnierLaw(const double friction_coefficient)
        : mu(friction_coefficient)
    {
      AssertThrow(mu >= 0., dealii::ExcMessage("friction coefficient < 0"));
    }


    double
    AlartCurnierLaw::friction_coefficient() const
    {
      return mu;
    }


    AlartCurnierResponse
    AlartCurnierLaw::evaluate(const dealii::Tensor<1, 3> &multiplier,
                              const dealii::Tensor<1, 3> &gap,
                              const dealii::Tensor<1, 3> &normal,
                              const double                augmentation) const
    {
      AssertThrow(augmentation > 0., dealii::ExcMessage("r must be > 0"));
      const double                r = augmentation;
      const dealii::Tensor<2, 3>  I = identity();
      const dealii::Tensor<1, 3> &n = normal;

      AlartCurnierResponse       result;
      const dealii::Tensor<1, 3> a        = multiplier - r * gap; // λ̂
      const double               a_N      = a * n;
      const dealii::Tensor<1, 3> a_T      = a - a_N * n;
      const double               norm_a_T = a_T.norm();
      result.augmented_force              = a;

      // D = dP/dλ̂; then dP/dλ = D, dP/dĝ = −r D (λ̂ = λ − r ĝ).
      dealii::Tensor<2, 3> D;
      // At the kink λ̂_N = 0 (a node touching with zero force, e.g. the
      // initial state of a sheet lying on the die) both branches belong to
      // the generalised Jacobian; the active one lets the tool carry load
      // from the first iteration, so only λ̂_N < 0 is open.
      if (a_N < 0.)
      {
        // Open: P = 0, F_sup = λ/r.
        result.state = ContactState::open;
      }
      else if (mu > 0. && (norm_a_T == 0. || norm_a_T < (1. - 1e-8) * mu * a_N))
      {
        // Stick: P = λ̂, so F_sup = ĝ; P does not depend on n at fixed λ̂.
        // On the cone (|λ̂_T| = μ λ̂_N up to rounding) slip is taken: a
        // pair that slipped in the last increment starts the next one on
        // the cone (ĝ_T = 0), and going on slipping is the likely answer;
        // calling it stick cost every increment two extra iterations.
        result.state = ContactState::stick;
        result.force = a;
        D            = I;
      }
      else
      {
        // Slip: P = λ̂_N (n + μ t), t = λ̂_T/|λ̂_T|. For μ > 0 here
        // |λ̂_T| > μ λ̂_N > 0, so t exists; for μ = 0 t is not needed.
        result.state = ContactState::slip;
        const dealii::Tensor<1, 3> t
          = (mu > 0. ? a_T / norm_a_T : dealii::Tensor<1, 3>());
        const dealii::Tensor<1, 3> n_mu_t = n + mu * t;
        result.force                      = a_N * n_mu_t;

        // dλ̂_N/dλ̂ = n, dt/dλ̂ = (I − n⊗n − t⊗t)/|λ̂_T|.
        D = outer_product(n_mu_t, n);
        // dλ̂_N/dn = λ̂, dλ̂_T/dn = −(n⊗λ̂ + λ̂_N I).
        result.dforce_dnormal = outer_product(n_mu_t, a) + a_N * I;
        if (mu > 0.)
        {
          const double               c   = mu * a_N / norm_a_T;
          const dealii::Tensor<2, 3> ItT = I - outer_product(t, t);
          D += c * (ItT - outer_product(n, n));
          result.dforce_dnormal -= c * (outer_product(n, a) + a_N * ItT);
        }
      }

      result.constraint_residual     = (multiplier - result.force) / r;
      result.dforce_dmultiplier      = D;
      result.dforce_dgap             = -r * D;
      result.dconstraint_dmultiplier = (I - D) / r;
      result.dconstraint_dgap        = D;
      result.dconstraint_dnormal     = -result.dforce_dnormal / r;
      return result;
    }
  } // namespace contact
} // namespace deepdraw
