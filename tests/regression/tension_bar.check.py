"""Large-strain uniaxial tension of a Hill'48 + Swift bar (tension_bar.prm).

Closed form (isochoric plastic flow, small elastic strains, uniaxial stress
along the rolling direction 1): with the logarithmic strain e = 0.5 t,
    sigma = Y(epbar) / sqrt(G + H),  epbar = (e - sigma/E) / sqrt(G + H)
(plastic-work equivalence: sigma de^p_11 = sigma_bar d epbar), and the current
section A = A0 exp(-e + (1 - 2 nu) sigma / E). The force on the quarter model
(A0 = 1 mm^2) must match within TOLERANCE = 3e-5 relative: the homogeneous
field is represented exactly, what remains is the time integration of the
hypoelastic law, measured 9.7e-6 at most (strain 0.125; increments 0.02 to
0.05 of prm/tension_bar.prm, the same for UMFPACK, KLU and MUMPS) and
1.3e-7 with increments of 0.005, so 3e-5 is 3 times what is achieved (the
issue's 1 % would have hidden a thousand times the error). Also: Newton
converges quadratically on plastic increments.
"""
import csv
import math
import sys

E, NU = 71000.0, 0.33
G, H = 0.5848, 0.4152
C, EPS0, N = 576.79, 0.01658, 0.3593
A0 = 1.0
TOLERANCE = 3e-5  # 3 x the largest error measured, 9.7e-6 (see above)


def closed_form_force(strain):
    root = math.sqrt(G + H)
    elastic_limit = C * EPS0 ** N / root
    if E * strain <= elastic_limit:
        sigma = E * strain
    else:
        # sigma - Y((strain - sigma/E)/root)/root = 0 is increasing in sigma.
        low, high = elastic_limit, E * strain
        for _ in range(200):
            sigma = 0.5 * (low + high)
            epbar = (strain - sigma / E) / root
            if sigma - C * (EPS0 + epbar) ** N / root > 0:
                high = sigma
            else:
                low = sigma
    return sigma * A0 * math.exp(-strain + (1 - 2 * NU) * sigma / E)


def main(output):
    failures = 0
    with open(output + "/reactions.csv") as f:
        rows = list(csv.DictReader(f))
    checked = 0
    for row in rows:
        t = float(row["load"])
        if t < 0.1:
            continue
        strain = 0.5 * t
        force = float(row["xmax_Fx"])
        expected = closed_form_force(strain)
        error = abs(force - expected) / expected
        ok = error <= TOLERANCE
        failures += not ok
        checked += 1
        print("%s strain %.3f force %.4f closed form %.4f rel. error %.2e"
              % ("ok  " if ok else "FAIL", strain, force, expected, error))
    if checked < 5:
        print("FAIL: too few rows checked")
        failures += 1

    # Quadratic convergence: log r_{k+1} / log r_k >= 1.8 wherever r_k is in
    # the asymptotic range (< 1e-1) and r_{k+1} above round-off (> 1e-12).
    with open(output + "/newton.csv") as f:
        newton = list(csv.DictReader(f))
    ratios = []
    for previous, current in zip(newton, newton[1:]):
        if previous["increment"] != current["increment"] or previous["load"] != current["load"]:
            continue
        r0, r1 = float(previous["force_residual"]), float(current["force_residual"])
        if r0 < 1e-1 and r1 > 1e-12 and float(previous["load"]) > 0.1:
            ratios.append(math.log(r1) / math.log(r0))
    print("convergence orders log r_k+1 / log r_k:", ["%.2f" % r for r in ratios])
    if not ratios or min(ratios) < 1.8:
        print("FAIL: Newton does not converge quadratically")
        failures += 1
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main(sys.argv[1])
