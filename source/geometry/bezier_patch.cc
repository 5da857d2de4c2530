#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deepdraw/geometry/bezier_patch.h>
#include <limits>

namespace deepdraw::geometry
{
  namespace
  {
    constexpr unsigned int basis_size = BezierPatch::max_degree + 1;

    // Bernstein polynomials B_i^n(t), i = 0..n, by the triangular scheme
    // B_i^k = (1 - t) B_i^(k-1) + t B_(i-1)^(k-1) (NURBS Book Alg. A1.3).
    // With derivatives, also B'_i^n = n (B_(i-1)^(n-1) - B_i^(n-1)) and
    // B''_i^n = n (n-1) (B_(i-2)^(n-2) - 2 B_(i-1)^(n-2) + B_i^(n-2)).
    template <bool with_derivatives>
    inline void
    bernstein(const unsigned int n,
              const double       t,
              double            *b,
              double            *db,
              double            *ddb)
    {
      double       lower_1[basis_size]; // degree n - 1
      double       lower_2[basis_size]; // degree n - 2
      const double s = 1. - t;
      b[0]           = 1.;
      for (unsigned int k = 1; k <= n; ++k)
      {
        if constexpr (with_derivatives)
        {
          if (k == n)
            std::copy(b, b + k, lower_1);
          if (k + 1 == n)
            std::copy(b, b + k, lower_2);
        }
        b[k] = t * b[k - 1];
        for (unsigned int i = k - 1; i >= 1; --i)
          b[i] = s * b[i] + t * b[i - 1];
        b[0] *= s;
      }
      if constexpr (with_derivatives)
      {
        for (unsigned int i = 0; i <= n; ++i)
        {
          const double left  = (i >= 1) ? lower_1[i - 1] : 0.;
          const double right = (i < n) ? lower_1[i] : 0.;
          db[i]              = n * (left - right);
          if (n >= 2)
          {
            const double l2 = (i >= 2) ? lower_2[i - 2] : 0.;
            const double l1 = (i >= 1 && i - 1 <= n - 2) ? lower_2[i - 1] : 0.;
            const double l0 = (i <= n - 2) ? lower_2[i] : 0.;
            ddb[i]          = n * (n - 1.) * (l2 - 2. * l1 + l0);
          }
          else
            ddb[i] = 0.;
        }
      }
    }

    inline double
    clamp_unit(const double t)
    {
      return std::min(1., std::max(0., t));
    }
  } // namespace


  BezierPatch::BezierPatch(const unsigned int                   degree_u,
                           const unsigned int                   degree_v,
                           const std::vector<dealii::Point<3>> &control_points,
                           const std::vector<double>           &weights)
      : p(degree_u)
      , q(degree_v)
      , points(control_points)
      , point_weights(weights)
  {
    AssertThrow(p >= 1 && q >= 1 && p <= max_degree && q <= max_degree,
                dealii::ExcMessage("Bezier patch degrees must lie in [1, "
                                   + std::to_string(max_degree) + "]"));
    const std::size_t n = (p + 1) * (q + 1);
    AssertThrow(points.size() == n && point_weights.size() == n,
                dealii::ExcMessage(
                  "A Bezier patch of degrees (p, q) needs "
                  "(p + 1)(q + 1) control points and weights"));
    homogeneous.resize(n);
    std::pair<dealii::Point<3>, dealii::Point<3>> corners(points[0], points[0]);
    double                                        largest_coordinate = 0.;
    for (std::size_t k = 0; k < n; ++k)
    {
      const double w = point_weights[k];
      AssertThrow(w > 0. && std::isfinite(w),
                  dealii::ExcMessage("Bezier weights must be positive"));
      for (unsigned int d = 0; d < 3; ++d)
      {
        AssertThrow(std::isfinite(points[k][d]),
                    dealii::ExcMessage("Control points must be finite"));
        homogeneous[k][d] = w * points[k][d];
        corners.first[d]  = std::min(corners.first[d], points[k][d]);
        corners.second[d] = std::max(corners.second[d], points[k][d]);
        largest_coordinate
          = std::max(largest_coordinate, std::abs(points[k][d]));
      }
      homogeneous[k][3] = w;
    }
    box = dealii::BoundingBox<3>(corners);
    scale
      = std::max(corners.first.distance(corners.second), largest_coordinate);

    // Two samples per polynomial degree resolve the shape well enough for
    // Newton to start in the basin of the closest point.
    n_samples_u = 2 * p + 1;
    n_samples_v = 2 * q + 1;
    samples.reserve(n_samples_u * n_samples_v);
    for (unsigned int j = 0; j < n_samples_v; ++j)
      for (unsigned int i = 0; i < n_samples_u; ++i)
        samples.push_back(
          value(i / (n_samples_u - 1.), j / (n_samples_v - 1.)));
  }


  unsigned int
  BezierPatch::degree_u() const
  {
    return p;
  }


  unsigned int
  BezierPatch::degree_v() const
  {
    return q;
  }


  const std::vector<dealii::Point<3>> &
  BezierPatch::control_points() const
  {
    return points;
  }


  const std::vector<double> &
  BezierPatch::weights() const
  {
    return point_weights;
  }


  const dealii::Point<3> &
  BezierPatch::control_point(const unsigned int i, const unsigned int j) const
  {
    return points[i + (p + 1) * j];
  }


  double
  BezierPatch::weight(const unsigned int i, const unsigned int j) const
  {
    return point_weights[i + (p + 1) * j];
  }


  dealii::Point<3>
  BezierPatch::value(const double u, const double v) const
  {
    double bu[basis_size], bv[basis_size];
    bernstein<false>(p, u, bu, nullptr, nullptr);
    bernstein<false>(q, v, bv, nullptr, nullptr);
    double sum[4] = {0., 0., 0., 0.};
    for (unsigned int j = 0; j <= q; ++j)
    {
      double row[4] = {0., 0., 0., 0.};
      for (unsigned int i = 0; i <= p; ++i)
      {
        const std::array<double, 4> &h = homogeneous[i + (p + 1) * j];
        for (unsigned int c = 0; c < 4; ++c)
          row[c] += bu[i] * h[c];
      }
      for (unsigned int c = 0; c < 4; ++c)
        sum[c] += bv[j] * row[c];
    }
    return dealii::Point<3>(sum[0] / sum[3], sum[1] / sum[3], sum[2] / sum[3]);
  }


  SurfacePoint
  BezierPatch::derivatives(const double u, const double v) const
  {
    double bu[basis_size], dbu[basis_size], ddbu[basis_size];
    double bv[basis_size], dbv[basis_size], ddbv[basis_size];
    bernstein<true>(p, u, bu, dbu, ddbu);
    bernstein<true>(q, v, bv, dbv, ddbv);

    // Homogeneous derivatives A = (w x, w): 0 value, 1 u, 2 v, 3 uu, 4 uv,
    // 5 vv, summed row by row (rows of constant j).
    double a[6][4] = {};
    for (unsigned int j = 0; j <= q; ++j)
    {
      double r0[4] = {0., 0., 0., 0.}, r1[4] = {0., 0., 0., 0.},
             r2[4] = {0., 0., 0., 0.};
      for (unsigned int i = 0; i <= p; ++i)
      {
        const std::array<double, 4> &h = homogeneous[i + (p + 1) * j];
        for (unsigned int c = 0; c < 4; ++c)
        {
          r0[c] += bu[i] * h[c];
          r1[c] += dbu[i] * h[c];
          r2[c] += ddbu[i] * h[c];
        }
      }
      for (unsigned int c = 0; c < 4; ++c)
      {
        a[0][c] += bv[j] * r0[c];
        a[1][c] += bv[j] * r1[c];
        a[2][c] += dbv[j] * r0[c];
        a[3][c] += bv[j] * r2[c];
        a[4][c] += dbv[j] * r1[c];
        a[5][c] += ddbv[j] * r0[c];
      }
    }

    // Quotient rule for x = A / W (NURBS Book Eq. 4.20):
    // x_u = (A_u - W_u x) / W, x_uu = (A_uu - 2 W_u x_u - W_uu x) / W,
    // x_uv = (A_uv - W_u x_v - W_v x_u - W_uv x) / W.
    const double w     = a[0][3];
    const double w_u   = a[1][3];
    const double w_v   = a[2][3];
    const double w_uu  = a[3][3];
    const double w_uv  = a[4][3];
    const double w_vv  = a[5][3];
    const double inv_w = 1. / w;

    SurfacePoint s;
    for (unsigned int d = 0; d < 3; ++d)
    {
      const double x   = a[0][d] * inv_w;
      const double x_u = (a[1][d] - w_u * x) * inv_w;
      const double x_v = (a[2][d] - w_v * x) * inv_w;
      s.position[d]    = x;
      s.x_u[d]         = x_u;
      s.x_v[d]         = x_v;
      s.x_uu[d]        = (a[3][d] - 2. * w_u * x_u - w_uu * x) * inv_w;
      s.x_uv[d]        = (a[4][d] - w_u * x_v - w_v * x_u - w_uv * x) * inv_w;
      s.x_vv[d]        = (a[5][d] - 2. * w_v * x_v - w_vv * x) * inv_w;
    }
    return s;
  }


  dealii::Tensor<1, 3>
  BezierPatch::unit_normal(const double u, const double v) const
  {
    return geometry::unit_normal(derivatives(u, v));
  }


  std::array<double, 2>
  BezierPatch::principal_curvatures(const double u, const double v) const
  {
    return compute_curvature(derivatives(u, v)).principal_curvatures;
  }


  const dealii::BoundingBox<3> &
  BezierPatch::bounding_box() const
  {
    return box;
  }


  double
  BezierPatch::length_scale() const
  {
    return scale;
  }


  PatchProjection
  BezierPatch::closest_point(const dealii::Point<3> &x) const
  {
    // Start from the nearest sample.
    unsigned int best_sample   = 0;
    double       best_distance = std::numeric_limits<double>::max();
    for (unsigned int k = 0; k < samples.size(); ++k)
    {
      const double d = (samples[k] - x).norm_square();
      if (d < best_distance)
      {
        best_distance = d;
        best_sample   = k;
      }
    }
    double u = (best_sample % n_samples_u) / (n_samples_u - 1.);
    double v = (best_sample / n_samples_u) / (n_samples_v - 1.);

    // Newton stops when its next step moves the foot by less than this;
    // with quadratic convergence the foot is then exact to about the square
    // of the previous step.
    const double step_tolerance = 1e-13 * scale;
    // Below this step length Newton is in its quadratic regime and needs no
    // line search (which round-off would only disturb).
    const double       search_threshold = 1e-6 * scale;
    const unsigned int max_iterations   = 50;

    PatchProjection      result;
    SurfacePoint         s   = derivatives(u, v);
    dealii::Tensor<1, 3> r   = s.position - x;
    double               f   = r.norm_square();
    double               g_u = r * s.x_u, g_v = r * s.x_v;
    unsigned int         iteration = 0;
    for (; iteration < max_iterations; ++iteration)
    {
      // Gradient g = J^T r and Hessian H = J^T J + r · x_ab of f / 2.
      const double j_uu = s.x_u * s.x_u, j_uv = s.x_u * s.x_v,
                   j_vv = s.x_v * s.x_v;
      double h_uu = j_uu + r * s.x_uu, h_uv = j_uv + r * s.x_uv,
             h_vv = j_vv + r * s.x_vv;

      // Bounds that hold the minimiser: at the bound, gradient outwards.
      const bool fixed_u = (u <= 0. && g_u > 0.) || (u >= 1. && g_u < 0.);
      const bool fixed_v = (v <= 0. && g_v > 0.) || (v >= 1. && g_v < 0.);
      double     du = 0., dv = 0.;
      if (!fixed_u && !fixed_v)
      {
        double det = h_uu * h_vv - h_uv * h_uv;
        if (!(h_uu > 0. && h_vv > 0. && det > 1e-12 * h_uu * h_vv))
        {
          // Not a descent direction: Gauss-Newton.
          h_uu = j_uu;
          h_uv = j_uv;
          h_vv = j_vv;
          det  = h_uu * h_vv - h_uv * h_uv;
        }
        du = -(h_vv * g_u - h_uv * g_v) / det;
        dv = -(h_uu * g_v - h_uv * g_u) / det;
      }
      else if (!fixed_u)
        du = -g_u / (h_uu > 0. ? h_uu : j_uu);
      else if (!fixed_v)
        dv = -g_v / (h_vv > 0. ? h_vv : j_vv);

      double       u_new = clamp_unit(u + du);
      double       v_new = clamp_unit(v + dv);
      const double step  = ((u_new - u) * s.x_u + (v_new - v) * s.x_v).norm();
      if (!(step > step_tolerance)) // also stops on NaN (degenerate point)
        break;

      SurfacePoint         s_new = derivatives(u_new, v_new);
      dealii::Tensor<1, 3> r_new = s_new.position - x;
      double               f_new = r_new.norm_square();
      if (step > search_threshold)
        for (unsigned int halving = 0; f_new > f && halving < 30; ++halving)
        {
          u_new = 0.5 * (u + u_new);
          v_new = 0.5 * (v + v_new);
          s_new = derivatives(u_new, v_new);
          r_new = s_new.position - x;
          f_new = r_new.norm_square();
        }
      u   = u_new;
      v   = v_new;
      s   = s_new;
      r   = r_new;
      f   = f_new;
      g_u = r * s.x_u;
      g_v = r * s.x_v;
    }

    result.u          = u;
    result.v          = v;
    result.point      = s;
    result.distance   = std::sqrt(f);
    result.iterations = iteration;
    // g_u / |x_u| = (x_foot - x) · x_u / |x_u|: the distance of x beyond the
    // edge along the outward tangent.
    if (u <= 0. && g_u > 0.)
      result.beyond_edge[0] = g_u / s.x_u.norm();
    if (u >= 1. && g_u < 0.)
      result.beyond_edge[1] = -g_u / s.x_u.norm();
    if (v <= 0. && g_v > 0.)
      result.beyond_edge[2] = g_v / s.x_v.norm();
    if (v >= 1. && g_v < 0.)
      result.beyond_edge[3] = -g_v / s.x_v.norm();
    return result;
  }


  BezierPatch
  BezierPatch::reversed_u() const
  {
    std::vector<dealii::Point<3>> reversed_points(points.size());
    std::vector<double>           reversed_weights(points.size());
    for (unsigned int j = 0; j <= q; ++j)
      for (unsigned int i = 0; i <= p; ++i)
      {
        reversed_points[i + (p + 1) * j]  = control_point(p - i, j);
        reversed_weights[i + (p + 1) * j] = weight(p - i, j);
      }
    return BezierPatch(p, q, reversed_points, reversed_weights);
  }
} // namespace deepdraw::geometry
