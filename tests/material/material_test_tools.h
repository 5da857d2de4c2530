// Helpers shared by the material-point tests: Kelvin (Mandel) 6-vectors,
// a small dense solver, a uniaxial tension/compression driver in an
// arbitrary direction of the sheet plane (mixed strain/stress control or
// pure stress control), Newton on the strain increment with the tangent of
// ElastoPlasticity, the finite-difference check of that tangent, and the
// published Yld2004-18p coefficients of AA2090-T3.
#ifndef deepdraw_tests_material_test_tools_h
#define deepdraw_tests_material_test_tools_h

#include "../test_utilities.h"

#include <array>
#include <cmath>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deepdraw/material/elasto_plasticity.h>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace material_test
{
  using namespace dealii;
  using deepdraw::material::ElastoPlasticity;
  using deepdraw::material::MaterialParameters;
  using deepdraw::material::MaterialPointState;
  using deepdraw::material::YieldCriterion;

  using Vector6 = std::array<double, 6>;
  using Matrix6 = std::array<Vector6, 6>;

  // Kelvin components in deal.II's order (11, 22, 33, 12, 13, 23).
  inline const std::array<std::pair<unsigned int, unsigned int>, 6> &
  kelvin_indices()
  {
    static const std::array<std::pair<unsigned int, unsigned int>, 6> ij
      = {{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}};
    return ij;
  }

  inline double
  kelvin_weight(const unsigned int I)
  {
    return I < 3 ? 1. : std::sqrt(2.);
  }

  inline Vector6
  to_kelvin(const SymmetricTensor<2, 3> &t)
  {
    Vector6 v;
    for (unsigned int I = 0; I < 6; ++I)
      v[I] = kelvin_weight(I)
             * t[kelvin_indices()[I].first][kelvin_indices()[I].second];
    return v;
  }

  inline SymmetricTensor<2, 3>
  from_kelvin(const Vector6 &v)
  {
    SymmetricTensor<2, 3> t;
    for (unsigned int I = 0; I < 6; ++I)
      t[kelvin_indices()[I].first][kelvin_indices()[I].second]
        = v[I] / kelvin_weight(I);
    return t;
  }

  inline Matrix6
  to_kelvin(const SymmetricTensor<4, 3> &t)
  {
    Matrix6 m;
    for (unsigned int I = 0; I < 6; ++I)
      for (unsigned int J = 0; J < 6; ++J)
      {
        const auto i = kelvin_indices()[I], j = kelvin_indices()[J];
        m[I][J] = kelvin_weight(I) * kelvin_weight(J)
                  * t[i.first][i.second][j.first][j.second];
      }
    return m;
  }

  // Solves A x = b (n <= 6) by Gaussian elimination with partial pivoting.
  inline std::array<double, 6>
  solve(std::array<std::array<double, 6>, 6> A,
        std::array<double, 6>                b,
        const unsigned int                   n)
  {
    for (unsigned int k = 0; k < n; ++k)
    {
      unsigned int p = k;
      for (unsigned int i = k + 1; i < n; ++i)
        if (std::abs(A[i][k]) > std::abs(A[p][k]))
          p = i;
      std::swap(A[k], A[p]);
      std::swap(b[k], b[p]);
      if (A[k][k] == 0.)
        throw std::runtime_error("singular matrix");
      for (unsigned int i = k + 1; i < n; ++i)
      {
        const double f = A[i][k] / A[k][k];
        for (unsigned int j = k; j < n; ++j)
          A[i][j] -= f * A[k][j];
        b[i] -= f * b[k];
      }
    }
    std::array<double, 6> x{};
    for (int k = n - 1; k >= 0; --k)
    {
      double s = b[k];
      for (unsigned int j = k + 1; j < n; ++j)
        s -= A[k][j] * x[j];
      x[k] = s / A[k][k];
    }
    return x;
  }

  // Rotation in the sheet plane: rows of Q are the load axes (1' = load
  // direction at angle theta from rolling, 2' = width, 3' = normal) in the
  // material frame. a_load = Q a_mat Q^T.
  inline Tensor<2, 3>
  load_axes(const double angle_in_degrees)
  {
    const double theta = angle_in_degrees * M_PI / 180.;
    Tensor<2, 3> Q;
    Q[0][0] = std::cos(theta);
    Q[0][1] = std::sin(theta);
    Q[1][0] = -std::sin(theta);
    Q[1][1] = std::cos(theta);
    Q[2][2] = 1.;
    return Q;
  }

  inline SymmetricTensor<2, 3>
  rotate(const Tensor<2, 3> &Q, const SymmetricTensor<2, 3> &a)
  {
    return symmetrize(Tensor<2, 3>(Q * Tensor<2, 3>(a) * transpose(Q)));
  }

  // Kelvin matrix R of a -> Q a Q^T (orthogonal): column J is the image of
  // the J-th Kelvin basis tensor.
  inline Matrix6
  kelvin_rotation(const Tensor<2, 3> &Q)
  {
    Matrix6 R;
    for (unsigned int J = 0; J < 6; ++J)
    {
      Vector6 e{};
      e[J]            = 1.;
      const Vector6 c = to_kelvin(rotate(Q, from_kelvin(e)));
      for (unsigned int I = 0; I < 6; ++I)
        R[I][J] = c[I];
    }
    return R;
  }

  // Uniaxial test in the direction `angle` of the sheet plane. The state
  // and the total strain are kept in the material frame, like the solver
  // does; the driver works in the load frame.
  class UniaxialDriver
  {
  public:
    UniaxialDriver(const ElastoPlasticity &material, const double angle)
        : material(material)
        , Q(load_axes(angle))
        , R(kelvin_rotation(Q))
    {
    }

    // Axial strain increment d prescribed, the five other stress
    // components in the load frame zero. Returns false if not converged.
    bool
    strain_step(const double d)
    {
      return solve_step(d, 0., false);
    }

    // Load-frame stress driven to s e1'(x)e1' (all six components).
    bool
    stress_step(const double s)
    {
      return solve_step(0., s, true);
    }

    // Stress, strain and back stress in the load frame.
    SymmetricTensor<2, 3>
    stress() const
    {
      return rotate(Q, state.stress);
    }
    SymmetricTensor<2, 3>
    strain() const
    {
      return rotate(Q, total_strain);
    }
    SymmetricTensor<2, 3>
    back_stress() const
    {
      return rotate(Q, state.back_stress);
    }

    MaterialPointState    state;
    SymmetricTensor<2, 3> total_strain; // material frame
    bool                  plastic    = false;
    unsigned int          iterations = 0;

  private:
    // Newton on the load-frame Kelvin strain increment e: for the mixed
    // case e_0 = d is fixed and the residual is sigma'_1..5; for the stress
    // case the residual is sigma' - s e1'(x)e1'.
    bool
    solve_step(const double d, const double s, const bool stress_control)
    {
      Vector6 e{};
      e[0]                     = d;
      const unsigned int first = stress_control ? 0 : 1;
      MaterialPointState new_state;
      for (iterations = 0; iterations < 50; ++iterations)
      {
        // Material-frame increment: a_mat = Q^T a_load Q.
        const SymmetricTensor<2, 3> increment
          = rotate(transpose(Q), from_kelvin(e));
        SymmetricTensor<4, 3> tangent;
        if (!material.update(state, increment, new_state, tangent, plastic))
          return false;
        Vector6 residual = to_kelvin(rotate(Q, new_state.stress));
        if (stress_control)
          residual[0] -= s;
        double norm = 0.;
        for (unsigned int I = first; I < 6; ++I)
          norm = std::max(norm, std::abs(residual[I]));
        if (norm <= 1e-10)
        {
          state = new_state;
          total_strain += increment;
          return true;
        }
        // Load-frame Kelvin tangent R T R^T; the sub-block of the
        // unknowns.
        const Matrix6 T = to_kelvin(tangent);
        Matrix6       A{};
        Vector6       b{};
        for (unsigned int I = first; I < 6; ++I)
        {
          for (unsigned int J = first; J < 6; ++J)
            for (unsigned int K = 0; K < 6; ++K)
              for (unsigned int L = 0; L < 6; ++L)
                A[I - first][J - first] += R[I][K] * T[K][L] * R[J][L];
          b[I - first] = -residual[I];
        }
        const Vector6 de = solve(A, b, 6 - first);
        for (unsigned int I = first; I < 6; ++I)
          e[I] += de[I - first];
      }
      return false;
    }

    const ElastoPlasticity &material;
    const Tensor<2, 3>      Q;
    const Matrix6           R;
  };

  inline MaterialParameters
  von_mises_parameters()
  {
    MaterialParameters p;
    p.hill_F = p.hill_G = p.hill_H = 0.5;
    p.hill_L = p.hill_M = p.hill_N = 1.5;
    return p;
  }

  inline SymmetricTensor<2, 3>
  strain(const double e11,
         const double e22,
         const double e33,
         const double e12,
         const double e13,
         const double e23)
  {
    SymmetricTensor<2, 3> e;
    e[0][0] = e11;
    e[1][1] = e22;
    e[2][2] = e33;
    e[0][1] = e12;
    e[0][2] = e13;
    e[1][2] = e23;
    return e;
  }

  // max |T_fd - T| / max |T| of the consistent tangent T of one update
  // against central differences of that update with step
  // h = 1e-5 max(|d_eps|, 1e-4); plastic tells whether the step was plastic.
  // 1e300 if an update fails or a perturbed step changes plastic.
  inline double
  tangent_error(const ElastoPlasticity      &material,
                const MaterialPointState    &old_state,
                const SymmetricTensor<2, 3> &increment,
                bool                        &plastic)
  {
    MaterialPointState    new_state;
    SymmetricTensor<4, 3> T, T_dummy;
    if (!material.update(old_state, increment, new_state, T, plastic))
      return 1e300;
    const double h         = 1e-5 * std::max(increment.norm(), 1e-4);
    double       max_error = 0., max_entry = 0.;
    for (unsigned int J = 0; J < 6; ++J)
    {
      // Raw entry J: both (k,l) and (l,k) move by h, so d sigma = 2 T h
      // for a shear column.
      SymmetricTensor<2, 3> perturbation;
      perturbation.access_raw_entry(J) = h;
      MaterialPointState plus, minus;
      bool               p_plus, p_minus;
      if (!material
             .update(old_state, increment + perturbation, plus, T_dummy, p_plus)
          || !material.update(old_state,
                              increment - perturbation,
                              minus,
                              T_dummy,
                              p_minus)
          || p_plus != plastic || p_minus != plastic)
        return 1e300;
      for (unsigned int I = 0; I < 6; ++I)
      {
        const double fd
          = (plus.stress.access_raw_entry(I) - minus.stress.access_raw_entry(I))
            / (2. * h);
        const double exact = T.access_raw_entry(6 * I + J) * (J < 3 ? 1. : 2.);
        max_error          = std::max(max_error, std::abs(fd - exact));
        max_entry          = std::max(max_entry, std::abs(exact));
      }
    }
    return max_error / max_entry;
  }

  // The tangent of `material` against finite differences (tangent_error,
  // tolerance 1e-6 of max |T|): every increment from the virgin state and
  // from a state pre-deformed plastically (with back stress if k > 0), all
  // plastic; then elastic loading from the virgin state and elastic
  // unloading from the pre-deformed one.
  inline void
  check_tangents(
    const ElastoPlasticity &material,
    const std::vector<std::pair<std::string, SymmetricTensor<2, 3>>>
      &increments)
  {
    MaterialPointState    virgin, predeformed;
    SymmetricTensor<4, 3> T;
    bool                  plastic = false;
    material.update(virgin,
                    strain(8e-3, -2e-3, -5e-3, 3e-3, 1e-3, -2e-3),
                    predeformed,
                    T,
                    plastic);
    deepdraw_test::check_true("  pre-deformation is plastic", plastic);
    const auto check = [&](const std::string           &name,
                           const MaterialPointState    &old_state,
                           const SymmetricTensor<2, 3> &increment,
                           const bool                   expect_plastic)
    {
      const double error
        = tangent_error(material, old_state, increment, plastic);
      deepdraw_test::check_true(
        "  " + name + (expect_plastic ? ": plastic step" : ": elastic step"),
        plastic == expect_plastic);
      deepdraw_test::check_close("  " + name + ": relative tangent error",
                                 error,
                                 0.,
                                 1e-6);
    };
    for (const auto &[name, increment] : increments)
    {
      check(name + ", virgin", virgin, increment, true);
      check(name + ", pre-deformed", predeformed, increment, true);
    }
    const SymmetricTensor<2, 3> small
      = strain(1e-4, -0.5e-4, 0.2e-4, 0.8e-4, 0.1e-4, -0.3e-4);
    check("elastic loading", virgin, small, false);
    check("elastic unloading", predeformed, -0.5 * small, false);
  }

  // A non-finite increment makes update() report failure (the caller cuts
  // the increment) instead of returning garbage.
  inline void
  check_nan_increment_fails(const ElastoPlasticity &material)
  {
    MaterialPointState    old_state, new_state;
    SymmetricTensor<4, 3> T;
    bool                  plastic;
    deepdraw_test::check_true(
      "NaN increment: update returns false",
      !material.update(old_state,
                       strain(std::nan(""), 0., 0., 0., 0., 0.),
                       new_state,
                       T,
                       plastic));
  }

  // Plastic strain eps - C^-1 : sigma of the driver, in the load frame.
  inline SymmetricTensor<2, 3>
  plastic_strain(const UniaxialDriver &driver, const MaterialParameters &p)
  {
    const double                E = p.youngs_modulus, nu = p.poissons_ratio;
    const SymmetricTensor<2, 3> s = driver.stress();
    return driver.strain()
           - ((1. + nu) * s - nu * trace(s) * unit_symmetric_tensor<3>()) / E;
  }

  // Strain-driven uniaxial tension at `angle` to the rolling direction, n
  // steps of d: ok if every step converged and the last was plastic; the
  // axial stress and the plastic strain increment of the last step (load
  // frame), whose ratio width / thickness is the r-value.
  struct UniaxialFlow
  {
    bool                  ok;
    double                stress;
    SymmetricTensor<2, 3> plastic_increment;

    double
    r() const
    {
      return plastic_increment[1][1] / plastic_increment[2][2];
    }
  };

  inline UniaxialFlow
  uniaxial_flow(const ElastoPlasticity &material,
                const double            angle,
                const unsigned int      n = 20,
                const double            d = 1e-3)
  {
    UniaxialDriver        driver(material, angle);
    SymmetricTensor<2, 3> previous, current;
    bool                  ok = true;
    for (unsigned int step = 0; step < n; ++step)
    {
      ok       = ok && driver.strain_step(d);
      previous = current;
      current  = plastic_strain(driver, material.get_parameters());
    }
    return {ok && driver.plastic, driver.stress()[0][0], current - previous};
  }

  // Yld2004-18p of AA2090-T3, a = 8 (Barlat et al., Int. J. Plasticity 21
  // (2005) 1009, as quoted in the TFEL/MFront documentation), in the
  // paper's order c12 c13 c21 c23 c31 c32 c44 c55 c66.
  inline MaterialParameters
  aa2090_t3_parameters()
  {
    MaterialParameters p;
    p.yield_criterion  = YieldCriterion::yld2004_18p;
    p.yld2004_c1       = {{-0.069888,
                           0.936408,
                           0.079143,
                           1.00306,
                           0.524741,
                           1.36318,
                           1.02377,
                           1.06906,
                           0.954322}};
    p.yld2004_c2       = {{0.981171,
                           0.476741,
                           0.575316,
                           0.866827,
                           1.14501,
                           -0.079294,
                           1.05166,
                           1.1471,
                           1.40462}};
    p.yld2004_exponent = 8.;
    return p;
  }

  // The entries of subsection Material that select Yld2004-18p with the
  // coefficients and exponent of p (for the tests that run a prm).
  inline std::string
  yld2004_prm_entries(const MaterialParameters &p)
  {
    const char *index[]
      = {"12", "13", "21", "23", "31", "32", "44", "55", "66"};
    std::ostringstream text;
    text.precision(17);
    text << "  set Yield criterion = Yld2004-18p\n  set Yld2004 exponent = "
         << p.yld2004_exponent << "\n";
    for (unsigned int k = 0; k < 9; ++k)
      text << "  set Yld2004 c'" << index[k] << " = " << p.yld2004_c1[k]
           << "\n  set Yld2004 c''" << index[k] << " = " << p.yld2004_c2[k]
           << "\n";
    return text.str();
  }

  // Root of a function changing sign on [a, b] by bisection to the last
  // bit: the independent scalar solver of the reference solutions.
  template <typename Function>
  double
  bisect(const Function &f, double a, double b)
  {
    double fa = f(a);
    for (unsigned int i = 0; i < 200; ++i)
    {
      const double c = 0.5 * (a + b);
      if (c == a || c == b)
        break;
      const double fc = f(c);
      if ((fc > 0.) == (fa > 0.))
      {
        a  = c;
        fa = fc;
      }
      else
        b = c;
    }
    return 0.5 * (a + b);
  }
} // namespace material_test

#endif
