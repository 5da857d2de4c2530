// solver::NewtonIncrement on small nonlinear systems with known solutions,
// independent of the forming problem (doc/theory.md §5):
// 1. a cubic spring chain with one prescribed unknown: converges to r = 0
//    (checked by evaluating r, not by the solver's own measures), the
//    prescribed unknown takes its value in the predictor, the order of
//    convergence is 2;
// 2. r(x) = atan(x) from x = 2: plain Newton is known to diverge from there
//    (|x| grows every step), the backtracking line search converges;
// 3. too few iterations allowed: the outcome says so;
// 4. a step that "breaks a point" (the system reports an inverted element
//    beyond |x| = 1): the predictor step is halved until it does not.
#include "test_utilities.h"

#include <cmath>
#include <deal.II/lac/full_matrix.h>
#include <deepdraw/solver/newton_increment.h>
#include <functional>

using namespace dealii;
using namespace deepdraw;
using solver::IncrementOutcome;

namespace
{
  // r(x) and dr/dx of n unknowns; unknown 0 is prescribed (value `target`
  // reached by the predictor) when prescribed = true.
  struct TestSystem : public solver::NewtonSystem
  {
    using Residual = std::function<
      void(const Vector<double> &, Vector<double> &, FullMatrix<double> &)>;

    TestSystem(const unsigned int n, Residual residual, const bool prescribed)
        : r(n)
        , J(n, n)
        , residual(std::move(residual))
        , prescribed(prescribed)
    {
    }

    IncrementOutcome
    assemble_at(const Vector<double> &x, bool) override
    {
      ++assemblies;
      if (x.linfty_norm() > breaking_point)
      {
        ++broken_points;
        return IncrementOutcome::inverted_element;
      }
      residual(x, r, J);
      x_assembled = x;
      return IncrementOutcome::converged;
    }

    bool
    solve_correction(Vector<double> &correction, const bool predictor) override
    {
      // Free block J_ff d_f = -r_f - J_f0 d_0, d_0 the prescribed step.
      const unsigned int n     = r.size();
      const unsigned int first = prescribed ? 1 : 0;
      const double       d0
        = prescribed ? (predictor ? target - x_assembled[0] : 0.) : 0.;
      FullMatrix<double> J_ff(n - first, n - first);
      Vector<double>     rhs(n - first), d(n - first);
      for (unsigned int i = first; i < n; ++i)
      {
        rhs[i - first] = -r[i] - (prescribed ? J(i, 0) * d0 : 0.);
        for (unsigned int j = first; j < n; ++j)
          J_ff(i - first, j - first) = J(i, j);
      }
      J_ff.gauss_jordan();
      J_ff.vmult(d, rhs);
      if (prescribed)
        correction[0] = d0;
      for (unsigned int i = first; i < n; ++i)
        correction[i] = d[i - first];
      return true;
    }

    bool
    is_prescribed(const types::global_dof_index i) const override
    {
      return prescribed && i == 0;
    }

    double
    free_norm() const
    {
      double sum = 0.;
      for (unsigned int i = prescribed ? 1 : 0; i < r.size(); ++i)
        sum += r[i] * r[i];
      return std::sqrt(sum);
    }

    solver::ResidualMeasures
    residual_measures() const override
    {
      solver::ResidualMeasures measures;
      measures.force = free_norm() / force_scale;
      return measures;
    }

    double
    merit() const override
    {
      return free_norm();
    }

    double
    correction_norm(const Vector<double> &correction) const override
    {
      return correction.l2_norm();
    }

    double
    relative_correction(const Vector<double> &x,
                        const double          norm) const override
    {
      return x.l2_norm() > 0. ? norm / x.l2_norm() : 0.;
    }

    void
    record_iteration(unsigned int,
                     const solver::ResidualMeasures &residuals,
                     double) override
    {
      recorded.push_back(residuals.force);
    }

    Vector<double>      r;
    FullMatrix<double>  J;
    Residual            residual;
    bool                prescribed;
    double              target         = 0.;
    double              force_scale    = 1.;
    double              breaking_point = 1e300;
    Vector<double>      x_assembled;
    unsigned int        assemblies    = 0;
    unsigned int        broken_points = 0;
    std::vector<double> recorded;
  };

  solver::NewtonParameters
  tight_parameters()
  {
    solver::NewtonParameters parameters;
    parameters.force_tolerance       = 1e-12;
    parameters.correction_tolerance  = 1e-12;
    parameters.maximum_iterations    = 30;
    parameters.stagnation_iterations = 0;
    return parameters;
  }

  // Three unknowns: springs 1-0, 2-1 with force k d + c d^3, and 2 loaded by
  // f; unknown 0 is prescribed.
  void
  spring_chain(const Vector<double> &x,
               Vector<double>       &r,
               FullMatrix<double>   &J)
  {
    const double k = 10., c = 50., f = 4.;
    r = 0.;
    J = 0.;
    for (unsigned int s = 0; s < 2; ++s)
    {
      const double d         = x[s + 1] - x[s];
      const double force     = k * d + c * d * d * d,
                   stiffness = k + 3. * c * d * d;
      r[s + 1] += force;
      r[s] -= force;
      J(s + 1, s + 1) += stiffness;
      J(s + 1, s) -= stiffness;
      J(s, s + 1) -= stiffness;
      J(s, s) += stiffness;
    }
    r[2] -= f;
  }
} // namespace

int
main()
{
  {
    std::cout << "spring chain, unknown 0 prescribed to 0.3" << std::endl;
    TestSystem system(3, spring_chain, true);
    system.target      = 0.3;
    system.force_scale = 4.;
    Vector<double>          x(3);
    unsigned int            iterations = 0;
    solver::NewtonIncrement newton(tight_parameters());
    const IncrementOutcome  outcome = newton.run(system, x, false, iterations);
    deepdraw_test::check_true("converged",
                              outcome == IncrementOutcome::converged);
    deepdraw_test::check_close("prescribed unknown", x[0], 0.3, 1e-15);
    // Independent check: the residual evaluated at the result.
    Vector<double>     r(3);
    FullMatrix<double> J(3, 3);
    spring_chain(x, r, J);
    deepdraw_test::check_close("free residual at the result",
                               std::hypot(r[1], r[2]),
                               0.,
                               4e-12);
    // Measured orders about 2 (until round-off).
    double lowest_order = 10.;
    for (unsigned int k = 0; k + 1 < system.recorded.size(); ++k)
      if (system.recorded[k] < 1e-2 && system.recorded[k + 1] > 1e-14)
        lowest_order = std::min(lowest_order,
                                std::log(system.recorded[k + 1])
                                  / std::log(system.recorded[k]));
    deepdraw_test::check_true("order of convergence "
                                + std::to_string(lowest_order) + " >= 1.8",
                              lowest_order >= 1.8 && lowest_order < 10.);
    deepdraw_test::check_true("iterations " + std::to_string(iterations)
                                + " <= 10",
                              iterations <= 10);
  }

  const auto arctangent
    = [](const Vector<double> &x, Vector<double> &r, FullMatrix<double> &J)
  {
    r[0]    = std::atan(x[0]);
    J(0, 0) = 1. / (1. + x[0] * x[0]);
  };
  {
    std::cout << "atan(x) = 0 from x = 2, plain Newton" << std::endl;
    TestSystem     system(1, arctangent, false);
    Vector<double> x(1);
    x[0]                                = 2.;
    solver::NewtonParameters parameters = tight_parameters();
    parameters.line_search_steps        = 0;
    unsigned int           iterations   = 0;
    const IncrementOutcome outcome
      = solver::NewtonIncrement(parameters).run(system, x, false, iterations);
    deepdraw_test::check_true("plain Newton does not converge ("
                                + solver::describe(outcome) + ")",
                              outcome != IncrementOutcome::converged);
  }
  {
    std::cout << "atan(x) = 0 from x = 2, line search" << std::endl;
    TestSystem     system(1, arctangent, false);
    Vector<double> x(1);
    x[0]                                = 2.;
    solver::NewtonParameters parameters = tight_parameters();
    parameters.line_search_steps        = 4;
    unsigned int           iterations   = 0;
    const IncrementOutcome outcome
      = solver::NewtonIncrement(parameters).run(system, x, false, iterations);
    deepdraw_test::check_true("line search converges",
                              outcome == IncrementOutcome::converged);
    deepdraw_test::check_close("root", x[0], 0., 1e-12);
  }
  {
    std::cout << "spring chain, 2 iterations allowed" << std::endl;
    TestSystem system(3, spring_chain, true);
    system.target                       = 0.3;
    system.force_scale                  = 4.;
    solver::NewtonParameters parameters = tight_parameters();
    parameters.maximum_iterations       = 2;
    Vector<double>         x(3);
    unsigned int           iterations = 0;
    const IncrementOutcome outcome
      = solver::NewtonIncrement(parameters).run(system, x, false, iterations);
    deepdraw_test::check_true("too many iterations",
                              outcome == IncrementOutcome::too_many_iterations);
  }
  {
    std::cout << "spring chain, points break beyond |x| = 1" << std::endl;
    // The tangent predictor from rest (stiffness k) moves unknown 2 to
    // 0.3 + 2 f / k = 1.1, beyond the breaking point; the solution has
    // |x| = 0.87.
    TestSystem system(3, spring_chain, true);
    system.target         = 0.3;
    system.force_scale    = 4.;
    system.breaking_point = 1.;
    Vector<double>          x(3);
    unsigned int            iterations = 0;
    solver::NewtonIncrement newton(tight_parameters());
    const IncrementOutcome  outcome = newton.run(system, x, false, iterations);
    deepdraw_test::check_true("converged after halving ("
                                + solver::describe(outcome) + ")",
                              outcome == IncrementOutcome::converged);
    deepdraw_test::check_true("a step broke a point and was halved ("
                                + std::to_string(system.broken_points) + ")",
                              system.broken_points > 0);
  }
  return deepdraw_test::summary();
}
