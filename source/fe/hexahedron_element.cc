#include <algorithm>
#include <cmath>
#include <deepdraw/fe/hexahedron_element.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <limits>

namespace deepdraw
{
  namespace fe
  {
    void
    EnhancedParameters::scale(const double ratio)
    {
      for (double &value : values)
        value *= ratio;
      for (double &value : correction)
        value *= ratio;
      for (double &value : evaluated_at)
        value *= ratio;
    }


    HexahedronElement::HexahedronElement(
      const ElementParameters          &parameters,
      const material::ElastoPlasticity &material,
      const FiniteElement<3>           &fe)
        : parameters(parameters)
        , material(material)
        , n_enhanced(n_enhanced_parameters(parameters.technology,
                                           parameters.points_through_thickness))
        , mean_dilatation(uses_mean_dilatation(parameters.technology))
    {
      AssertDimension(fe.n_dofs_per_cell(), dofs_per_cell);
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
      {
        local_component[i] = fe.system_to_component_index(i).first;
        local_node[i]      = fe.system_to_component_index(i).second;
      }
    }


    ElementStatus
    HexahedronElement::integrate(const CellGeometry           &geometry,
                                 const double                 *du,
                                 const double                 *alpha,
                                 const QuadraturePointHistory *old_history,
                                 QuadraturePointHistory       *trial_history,
                                 double                       *residual,
                                 Tensor<4, 3>                 *tangents,
                                 unsigned int &plastic_points) const
    {
      const unsigned int n = dofs_per_cell + n_enhanced;
      Tensor<1, 3>       u[8], alpha_m[max_modes];
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        u[local_node[i]][local_component[i]] = du[i];
      for (unsigned int k = 0; k < n_enhanced; ++k)
        alpha_m[k / 3][k % 3] = alpha[k];
      // Cell-average trace of the compatible H (mean dilatation).
      double mean_divergence = 0.;
      for (unsigned int a = 0; a < 8; ++a)
        mean_divergence += u[a] * geometry.mean_gradient[a];

      std::fill(residual, residual + n, 0.);
      Tensor<2, 3> P;
      for (unsigned int q = 0; q < geometry.n_points(); ++q)
      {
        const Tensor<1, 3> *g       = &geometry.gradient[q * 8];
        const Tensor<1, 3> *g_modes = &geometry.mode_gradient[q * max_modes];
        // H: compatible part (its trace replaced by the cell average with
        // mean dilatation) plus the enhanced part.
        Tensor<2, 3> H;
        for (unsigned int a = 0; a < 8; ++a)
          H += outer_product(u[a], g[a]);
        if (mean_dilatation)
        {
          const double correction = (mean_divergence - trace(H)) / 3.;
          for (unsigned int d = 0; d < 3; ++d)
            H[d][d] += correction;
        }
        for (unsigned int m = 0; m < n_enhanced / 3; ++m)
          H += outer_product(alpha_m[m], g_modes[m]);

        bool              plastic = false;
        const PointStatus status
          = update_quadrature_point(material,
                                    old_history[q],
                                    H,
                                    trial_history[q],
                                    P,
                                    tangents != nullptr ? &tangents[q]
                                                        : nullptr,
                                    plastic);
        if (status == PointStatus::inverted)
          return ElementStatus::inverted;
        if (status != PointStatus::ok)
          return ElementStatus::return_mapping_failed;
        plastic_points += plastic;

        // r_j = w G_j : P with G_j = e_c (x) v_j + beta_j I.
        const double w = geometry.JxW[q];
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          const unsigned int a = local_node[i], c = local_component[i];
          double             value = P[c] * g[a];
          if (mean_dilatation)
            value += (geometry.mean_gradient[a][c] - g[a][c]) / 3. * trace(P);
          residual[i] += w * value;
        }
        for (unsigned int k = 0; k < n_enhanced; ++k)
          residual[dofs_per_cell + k] += w * (P[k % 3] * g_modes[k / 3]);
        if (tangents != nullptr)
          tangents[q] *= w;
      }
      return ElementStatus::ok;
    }


    namespace
    {
      // K_ij += G_i : A : G_j for i, j in [first, n) at one point (A
      // weighted), in two sparse steps: T_j = A : G_j, stored as
      // T[c][m][j] = (T_j)_cm, then
      //   K_ij += sum_m v_i[m] T[c_i][m][j] + beta_i tr T_j,
      // contiguous in j. The trace terms only with mean dilatation.
      template <bool with_trace>
      void
      add_point_tangent(const Tensor<4, 3>        &A,
                        const unsigned int        *component,
                        const Tensor<1, 3> *const *vector,
                        const double              *beta,
                        const unsigned int         first,
                        const unsigned int         n,
                        double                    *matrix)
      {
        double A_trace[3][3]; // sum_l A[c][m][l][l]
        if constexpr (with_trace)
          for (unsigned int c = 0; c < 3; ++c)
            for (unsigned int m = 0; m < 3; ++m)
              A_trace[c][m] = A[c][m][0][0] + A[c][m][1][1] + A[c][m][2][2];
        alignas(64) double T[3][3][max_element_size];
        double             trace_T[max_element_size];
        for (unsigned int j = first; j < n; ++j)
        {
          const Tensor<1, 3> &v = *vector[j];
          const unsigned int  d = component[j];
          for (unsigned int c = 0; c < 3; ++c)
            for (unsigned int m = 0; m < 3; ++m)
            {
              const Tensor<1, 3> &A_cmd = A[c][m][d];
              double              value
                = A_cmd[0] * v[0] + A_cmd[1] * v[1] + A_cmd[2] * v[2];
              if constexpr (with_trace)
                value += beta[j] * A_trace[c][m];
              T[c][m][j] = value;
            }
          if constexpr (with_trace)
            trace_T[j] = T[0][0][j] + T[1][1][j] + T[2][2][j];
        }
        for (unsigned int i = first; i < n; ++i)
        {
          const Tensor<1, 3> &v   = *vector[i];
          const double       *T_0 = T[component[i]][0];
          const double       *T_1 = T[component[i]][1];
          const double       *T_2 = T[component[i]][2];
          double             *K_i = matrix + i * n;
          for (unsigned int j = first; j < n; ++j)
          {
            double value = v[0] * T_0[j] + v[1] * T_1[j] + v[2] * T_2[j];
            if constexpr (with_trace)
              value += beta[i] * trace_T[j];
            K_i[j] += value;
          }
        }
      }
    } // namespace


    void
    HexahedronElement::tangent_matrix(const CellGeometry &geometry,
                                      const Tensor<4, 3> *tangents,
                                      const unsigned int  first,
                                      double             *matrix) const
    {
      const unsigned int n = dofs_per_cell + n_enhanced;
      for (unsigned int i = first; i < n; ++i)
        std::fill(matrix + i * n + first, matrix + (i + 1) * n, 0.);
      // Column j: G_j = e_{component[j]} (x) vector[j] + beta[j] I.
      unsigned int        component[max_element_size];
      const Tensor<1, 3> *vector[max_element_size];
      double              beta[max_element_size];
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        component[i] = local_component[i];
      for (unsigned int k = 0; k < n_enhanced; ++k)
      {
        component[dofs_per_cell + k] = k % 3;
        beta[dofs_per_cell + k]      = 0.;
      }
      for (unsigned int q = 0; q < geometry.n_points(); ++q)
      {
        const Tensor<1, 3> *g       = &geometry.gradient[q * 8];
        const Tensor<1, 3> *g_modes = &geometry.mode_gradient[q * max_modes];
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          const unsigned int a = local_node[i], c = local_component[i];
          vector[i] = &g[a];
          beta[i]   = mean_dilatation
                        ? (geometry.mean_gradient[a][c] - g[a][c]) / 3.
                        : 0.;
        }
        for (unsigned int k = 0; k < n_enhanced; ++k)
          vector[dofs_per_cell + k] = &g_modes[k / 3];
        if (mean_dilatation)
          add_point_tangent<true>(tangents[q],
                                  component,
                                  vector,
                                  beta,
                                  first,
                                  n,
                                  matrix);
        else
          add_point_tangent<false>(tangents[q],
                                   component,
                                   vector,
                                   beta,
                                   first,
                                   n,
                                   matrix);
      }
    }


    namespace
    {
      // In-place inverse of the n x n row-major matrix a (Gauss-Jordan with
      // partial pivoting); false if it is singular or not finite.
      bool
      invert_in_place(double *a, const unsigned int n)
      {
        unsigned int pivot_row[max_enhanced];
        double       scale = 0.;
        for (unsigned int i = 0; i < n * n; ++i)
          scale = std::max(scale, std::abs(a[i]));
        if (!(scale > 0.) || !std::isfinite(scale))
          return false;
        for (unsigned int k = 0; k < n; ++k)
        {
          unsigned int p = k;
          for (unsigned int i = k + 1; i < n; ++i)
            if (std::abs(a[i * n + k]) > std::abs(a[p * n + k]))
              p = i;
          if (!(std::abs(a[p * n + k]) > 1e-14 * scale))
            return false;
          pivot_row[k] = p;
          if (p != k)
            for (unsigned int j = 0; j < n; ++j)
              std::swap(a[k * n + j], a[p * n + j]);
          const double inverse_pivot = 1. / a[k * n + k];
          a[k * n + k]               = 1.;
          for (unsigned int j = 0; j < n; ++j)
            a[k * n + j] *= inverse_pivot;
          for (unsigned int i = 0; i < n; ++i)
            if (i != k)
            {
              const double factor = a[i * n + k];
              a[i * n + k]        = 0.;
              for (unsigned int j = 0; j < n; ++j)
                a[i * n + j] -= factor * a[k * n + j];
            }
        }
        // Undo the row swaps as column swaps, in reverse order.
        for (unsigned int k = n; k-- > 0;)
          if (pivot_row[k] != k)
            for (unsigned int i = 0; i < n; ++i)
              std::swap(a[i * n + k], a[i * n + pivot_row[k]]);
        return true;
      }
    } // namespace


    ElementStatus
    HexahedronElement::evaluate(const CellGeometry           &geometry,
                                const double                 *du,
                                const QuadraturePointHistory *old_history,
                                QuadraturePointHistory       *trial_history,
                                EnhancedParameters           &enhanced,
                                double                       *residual,
                                FullMatrix<double>           *matrix,
                                unsigned int &plastic_points) const
    {
      constexpr unsigned int nu = dofs_per_cell;
      Tensor<4, 3>           tangents[max_weighted_points];
      if (n_enhanced == 0)
      {
        const ElementStatus status
          = integrate(geometry,
                      du,
                      nullptr,
                      old_history,
                      trial_history,
                      residual,
                      matrix != nullptr ? tangents : nullptr,
                      plastic_points);
        // FullMatrix stores its entries row by row: the 24 x 24 matrix is
        // integrated in place.
        if (status == ElementStatus::ok && matrix != nullptr)
          tangent_matrix(geometry, tangents, 0, &(*matrix)(0, 0));
        return status;
      }

      // The enhanced parameters: predicted from the last linearisation,
      // then Newton on r_alpha(du, alpha) = 0 at fixed du.
      const unsigned int ne = n_enhanced, n = nu + ne;
      double             alpha[max_enhanced];
      for (unsigned int k = 0; k < ne; ++k)
      {
        alpha[k] = enhanced.values[k] + enhanced.correction[k];
        for (unsigned int j = 0; j < nu; ++j)
          alpha[k] += enhanced.sensitivity[k * nu + j]
                      * (du[j] - enhanced.evaluated_at[j]);
      }
      double       full_residual[max_element_size];
      double       K[max_element_size * max_element_size];
      double       K_aa_inverse[max_enhanced * max_enhanced];
      unsigned int points_plastic = 0;
      // Newton with backtracking: a step that raises |r_alpha| (a point
      // switching between elastic and plastic) is halved.
      double alpha_base[max_enhanced], step_direction[max_enhanced];
      double base_norm = std::numeric_limits<double>::infinity(), step = 0.;
      bool   restarted = false;
      // Iterations used up: the last accepted alpha is evaluated once more
      // and condensed as it is (D189).
      bool pending = false;
      // The element's forces are measured against at least 1e-8 of the
      // forces of its stress at the increment's start, |sigma_n| V^(2/3):
      // where the increment ends stress-free (a release, D152) its forces
      // are the round-off of the stresses that cancelled, and a criterion
      // relative to them alone is never met.
      double old_force_scale = 0.;
      {
        double volume = 0.;
        for (unsigned int q = 0; q < geometry.n_points(); ++q)
          volume += geometry.JxW[q];
        for (unsigned int q = 0; q < geometry.n_points(); ++q)
          old_force_scale
            = std::max(old_force_scale, old_history[q].state.stress.norm());
        old_force_scale *= 1e-8 * std::pow(volume, 2. / 3.);
      }
      for (unsigned int iteration = 0;; ++iteration)
      {
        if (iteration >= parameters.enhanced_max_iterations)
        {
          if (!parameters.iterate_enhanced_globally || pending
              || !(base_norm < std::numeric_limits<double>::infinity()))
            return ElementStatus::enhanced_not_converged;
          pending = true;
          step    = 0.;
          std::copy(alpha_base, alpha_base + ne, alpha);
        }
        points_plastic             = 0;
        const ElementStatus status = integrate(geometry,
                                               du,
                                               alpha,
                                               old_history,
                                               trial_history,
                                               full_residual,
                                               tangents,
                                               points_plastic);
        double force_scale = old_force_scale, enhanced_residual = 0., norm = 0.;
        for (unsigned int i = 0; i < nu; ++i)
          force_scale = std::max(force_scale, std::abs(full_residual[i]));
        for (unsigned int k = 0; k < ne; ++k)
        {
          const double r    = full_residual[nu + k];
          enhanced_residual = std::max(enhanced_residual, std::abs(r));
          norm += r * r;
        }
        const bool failed_point
          = status != ElementStatus::ok || !std::isfinite(enhanced_residual);
        if ((failed_point || norm > base_norm) && step > 1. / 32.)
        {
          step *= 0.5;
          for (unsigned int k = 0; k < ne; ++k)
            alpha[k] = alpha_base[k] + step * step_direction[k];
          continue;
        }
        if (failed_point && iteration == 0 && !restarted)
        {
          // The prediction failed: start again from alpha = 0.
          restarted = true;
          std::fill(alpha, alpha + ne, 0.);
          continue;
        }
        if (failed_point)
          return status != ElementStatus::ok
                   ? status
                   : ElementStatus::enhanced_not_converged;
        // K_aa alone for the local Newton step; the whole K once alpha
        // has converged.
        tangent_matrix(geometry, tangents, nu, K);
        for (unsigned int k = 0; k < ne; ++k)
          for (unsigned int l = 0; l < ne; ++l)
            K_aa_inverse[k * ne + l] = K[(nu + k) * n + nu + l];
        if (!invert_in_place(K_aa_inverse, ne))
          return ElementStatus::enhanced_not_converged;
        // A pending element is evaluated at an alpha that already missed
        // the tolerance: it is condensed as it is.
        if (enhanced_residual <= parameters.enhanced_tolerance * force_scale
            || pending)
          break;
        base_norm = norm;
        step      = 1.;
        for (unsigned int k = 0; k < ne; ++k)
        {
          alpha_base[k]     = alpha[k];
          step_direction[k] = 0.;
          for (unsigned int l = 0; l < ne; ++l)
            step_direction[k]
              -= K_aa_inverse[k * ne + l] * full_residual[nu + l];
          alpha[k] += step_direction[k];
        }
      }
      plastic_points += points_plastic;
      tangent_matrix(geometry, tangents, 0, K);

      // Condensation. correction = -K_aa^{-1} r_a (the remaining Newton
      // step of alpha), sensitivity = d alpha / d du = -K_aa^{-1} K_au.
      for (unsigned int k = 0; k < ne; ++k)
      {
        double c = 0.;
        for (unsigned int l = 0; l < ne; ++l)
          c -= K_aa_inverse[k * ne + l] * full_residual[nu + l];
        enhanced.correction[k] = c;
        enhanced.values[k]     = alpha[k];
        // Row by row of K_au, contiguous in j (vectorised).
        double *sensitivity = &enhanced.sensitivity[k * nu];
        std::fill(sensitivity, sensitivity + nu, 0.);
        for (unsigned int l = 0; l < ne; ++l)
        {
          const double  factor = -K_aa_inverse[k * ne + l];
          const double *K_au_l = K + (nu + l) * n;
          for (unsigned int j = 0; j < nu; ++j)
            sensitivity[j] += factor * K_au_l[j];
        }
      }
      // The global Newton predicts alpha from this linearisation
      // (values + correction + sensitivity du): Simo and Rifai's condensed
      // update, without the local loop having converged.
      for (unsigned int j = 0; j < nu; ++j)
        enhanced.evaluated_at[j] = du[j];
      // r* = r_u + K_ua correction, K* = K_uu + K_ua sensitivity.
      for (unsigned int i = 0; i < nu; ++i)
      {
        const double *K_ua = K + i * n + nu;
        double        r    = full_residual[i];
        for (unsigned int k = 0; k < ne; ++k)
          r += K_ua[k] * enhanced.correction[k];
        residual[i] = r;
        if (matrix == nullptr)
          continue;
        double *K_i = &(*matrix)(i, 0);
        std::copy(K + i * n, K + i * n + nu, K_i);
        for (unsigned int k = 0; k < ne; ++k)
        {
          const double  factor      = K_ua[k];
          const double *sensitivity = &enhanced.sensitivity[k * nu];
          for (unsigned int j = 0; j < nu; ++j)
            K_i[j] += factor * sensitivity[j];
        }
      }
      return pending ? ElementStatus::enhanced_pending : ElementStatus::ok;
    }
  } // namespace fe
} // namespace deepdraw
