"""Checks of viscous_stabilization.prm, a stage's viscous stabilization
(D208).

Independent expectation: with Poisson's ratio 0 the bar is in uniaxial
stress, a one-dimensional bar of 4 linear elements (h = 2.5 mm, EA/h =
206000 * 1 / 2.5 N/mm). Its three interior node columns carry the
viscous force c(t) V (u - u_old) / dt, V = A h = 2.5 mm^3 (the lumped share
of the initial volume), in each increment of dt = 0.25 (implicit Euler);
u = 0 at x = 0 (the symmetry plane), u = 1e-3 t at x = 10. Solving these
three equations per increment (below) gives the force on the pulled face;
deepdraw's must match it to 1e-4 relative: the Newton tolerance is
1e-10, and the large-strain terms the 1D bar leaves out are of the order
of the strain, 1e-4 at t = 1 (measured 1.1e-5 at t = 0.25 to 5.0e-5 at
t = 1, growing with the strain).
- t = 0.25 ... 0.75 (c = 1000): the viscous forces carry 12-26 % of the
  force, so a stabilization that did nothing would fail;
- t = 1 (c = 0, the stage's end): the elastic force E A u / L, 20.6 N.
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from script_test import Checks, csv_rows as rows  # noqa: E402

E, A, L, N = 206000.0, 1.0, 10.0, 4
H = L / N


def coefficient(t):
    return 1000.0 * min(1.0, 4.0 * (1.0 - t))


def bar_forces(loads):
    """Force on the pulled end after each increment of the 1D bar."""
    k = E * A / H
    u = [0.0] * (N + 1)
    forces = {}
    old_t = 0.0
    for t in loads:
        dt = t - old_t
        damping = coefficient(t) * A * H / dt
        old = list(u)
        u[N] = 1e-3 * t
        # interior rows: k (2 u_j - u_j-1 - u_j+1) + d (u_j - old_j) = 0,
        # tridiagonal, solved by elimination
        diagonal = [2 * k + damping] * (N - 1)
        rhs = [damping * old[j] for j in range(1, N)]
        rhs[-1] += k * u[N]
        for j in range(1, N - 1):
            factor = -k / diagonal[j - 1]
            diagonal[j] -= factor * -k
            rhs[j] -= factor * rhs[j - 1]
        interior = [0.0] * (N - 1)
        for j in reversed(range(N - 1)):
            upper = -k * interior[j + 1] if j + 1 < N - 1 else 0.0
            interior[j] = (rhs[j] - upper) / diagonal[j]
        u[1:N] = interior
        forces[t] = k * (u[N] - u[N - 1])
        old_t = t
    return forces


def main(output):
    checks = Checks()
    reactions = [row for row in rows(output + "/reactions.csv")
                 if row["load"] > 0]
    expected = bar_forces([row["load"] for row in reactions])
    if [row["load"] for row in reactions] != [0.25, 0.5, 0.75, 1.0]:
        checks.failures.append("increments end at %s"
                               % [row["load"] for row in reactions])
    for row in reactions:
        t = row["load"]
        elastic = E * A * 1e-3 * t / L
        print("t = %g: viscous part of the force %.4g N of %.4g"
              % (t, expected[t] - elastic, expected[t]))
        checks.check("t = %g: force on the pulled face" % t, row["xmax_Fx"],
                     expected[t], 1e-4)
    checks.check("t = 1: no viscous force left", expected[1.0],
                 E * A * 1e-3 / L, 1e-12)
    return checks.exit_code()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
