"""Square-cup result tables on process_tables.prm (see its header).

Closed form (small strain, linear elasticity, exact for the homogeneous
state of Q1 elements up to geometric nonlinearity): the plate carries
sigma_xx from eps_xx = -0.02 t / L (xmax pushed in), sigma_yy = 0 and
sigma_zz = -p, p = F(t) / (L W), F(t) = 30 + 200 t, so that
  eps_yy = -nu eps_xx + nu (1 + nu) p / E,
  eps_zz = -nu eps_xx - (1 - nu^2) p / E.
The finite-strain, updated-Lagrangian solution differs by O(strain) < 1e-3
relative in each term; the terms partly cancel (eps_zz changes sign between
the two travels), so the draw-in and thickness strain are asserted to 2e-3
of the sum of the magnitudes of their terms.

Asserted:
 (i)   the headers of punch_force.csv, draw_in.csv and the thickness files;
 (ii)  holder_force_N = F(t) to 1e-8 relative (the holder equation is in
       the Newton system, converged to 1e-12);
 (iii) punch_force_N = the punch force of tools.csv along the punch motion
       d = +z (translation 0; 0; t) to 1e-8, and = F(t) (equilibrium of the
       plate, no other support along z) to 1e-8; holder_z_mm = holder_uz of
       tools.csv;
 (iv)  thickness files at 0.02 and 0.05 mm, none at 0.1 (beyond the punch
       travel); OX: one row per column on y = 0, s0 = 0 ... L; OD: the
       crossings of x = y with the grid lines x = i/2, y = 2j/3, s0 =
       sqrt(2) x; thickness strain = eps_zz at every point;
 (v)   DX = 0.02 t (prescribed, 1e-9 mm), DY = -eps_yy W (< 0: the
       Poisson effect pushes the edge y = W out), DD from the corner at
       (L - DX, W - DY): DD = hypot(L, W) - hypot(L - DX, W - DY)
       to 1e-9 mm with the computed DX, DY (the corner lies on both
       edges) and to 2e-3 (DX + |DY|) with the closed-form ones.
"""
import csv
import math
import os
import sys

L, W, T, E, NU = 2.0, 2.0, 0.5, 71000.0, 0.33
NX, NY = 4, 3


def force(t):
    return 30.0 + 200.0 * t


def strains(t):
    """eps_yy, eps_zz and the sums of the magnitudes of their terms."""
    eps_xx = -0.02 * t / L
    p = force(t) / (L * W)
    yy = (-NU * eps_xx, NU * (1 + NU) * p / E)
    zz = (-NU * eps_xx, -(1 - NU * NU) * p / E)
    return (sum(yy), sum(abs(e) for e in yy), sum(zz),
            sum(abs(e) for e in zz))


failures = 0


def check(what, ok, text):
    global failures
    failures += not ok
    print("%s %s: %s" % ("ok  " if ok else "FAIL", what, text))


def relative(actual, expected):
    return abs(actual - expected) / abs(expected)


def read(path):
    with open(path) as f:
        reader = csv.reader(f)
        header = next(reader)
        return header, [[float(v) for v in row] for row in reader]


def main(output):
    header, punch = read(output + "/punch_force.csv")
    check("punch_force.csv header", header == [
        "punch_travel_mm", "punch_force_N", "holder_force_N", "holder_z_mm"],
        str(header))
    header, draw_in = read(output + "/draw_in.csv")
    check("draw_in.csv header",
          header == ["punch_travel_mm", "DX_mm", "DY_mm", "DD_mm"],
          str(header))
    with open(output + "/tools.csv") as f:
        tools = list(csv.DictReader(f))
    check("one row per tools.csv row", len(punch) == len(tools) == len(
        draw_in) and len(tools) >= 5, "%d %d %d" % (len(punch), len(draw_in),
                                                    len(tools)))

    for row, draw, tool in zip(punch, draw_in, tools):
        t, punch_force, holder_force, holder_z = row
        check("travel", t == float(tool["load"]) == draw[0], "t %g" % t)
        if t == 0:
            # Nothing is solved yet: no contact force, no draw-in.
            check("t 0 row", punch_force == holder_force == 0
                  and draw[1:] == [0, 0, 0], str(row + draw))
            continue
        F = force(t)
        # d = +z: the punch moves up by t.
        from_tools = sum(float(tool["Punch_F" + c]) * d
                         for c, d in zip("xyz", (0.0, 0.0, 1.0)))
        check("t %.4f holder force" % t, relative(holder_force, F) <= 1e-8,
              "%.12g vs F(t) = %.12g" % (holder_force, F))
        check("t %.4f punch force" % t,
              relative(punch_force, from_tools) <= 1e-8
              and relative(punch_force, F) <= 1e-8,
              "%.12g vs tools.csv %.12g, F(t) %.12g"
              % (punch_force, from_tools, F))
        check("t %.4f holder z" % t, holder_z == float(tool["holder_uz"]),
              "%.12g vs tools.csv %s" % (holder_z, tool["holder_uz"]))

        eps_yy, scale_yy, _, _ = strains(t)
        DX, DY, DD = draw[1:]
        expected_dx, expected_dy = 0.02 * t, -eps_yy * W
        expected_dd = math.hypot(L, W) - math.hypot(L - expected_dx,
                                                    W - expected_dy)
        consistent_dd = math.hypot(L, W) - math.hypot(L - DX, W - DY)
        check("t %.4f draw-in" % t,
              abs(DX - expected_dx) <= 1e-9
              and abs(DY - expected_dy) <= 2e-3 * scale_yy * W
              and abs(DD - consistent_dd) <= 1e-9
              and abs(DD - expected_dd) <= 2e-3 * (expected_dx
                                                  + abs(expected_dy)),
              "DX %.6e (%.6e) DY %.6e (%.6e) DD %.6e (%.6e, from DX DY %.6e)"
              % (DX, expected_dx, DY, expected_dy, DD, expected_dd,
                 consistent_dd))

    s0_ox = [i * L / NX for i in range(NX + 1)]
    x_od = sorted(set([round(i * L / NX, 12) for i in range(NX + 1)]
                      + [round(j * W / NY, 12) for j in range(NY + 1)]))
    s0_od = [math.sqrt(2) * x for x in x_od]
    for travel, name in ((0.02, "0.02"), (0.05, "0.05")):
        _, _, eps_zz, scale_zz = strains(travel)
        for axis, expected_s0 in (("OX", s0_ox), ("OD", s0_od)):
            path = "%s/thickness_%s_%smm.csv" % (output, axis, name)
            if not os.path.exists(path):
                check(path, False, "missing")
                continue
            header, rows = read(path)
            check(os.path.basename(path) + " header",
                  header == ["s0_mm", "thickness_strain"], str(header))
            s0 = [r[0] for r in rows]
            check(os.path.basename(path) + " s0",
                  len(s0) == len(expected_s0) and all(
                      abs(a - b) <= 1e-9 for a, b in zip(s0, expected_s0)),
                  " ".join("%.6g" % s for s in s0))
            worst = max(abs(r[1] - eps_zz) for r in rows) / scale_zz
            check(os.path.basename(path) + " thickness strain",
                  worst <= 2e-3,
                  "%s vs eps_zz %.6e, worst error %.1e of the terms"
                  % (" ".join("%.6e" % r[1] for r in rows), eps_zz, worst))
    for axis in ("OX", "OD"):
        path = "%s/thickness_%s_0.1mm.csv" % (output, axis)
        check("no file beyond the punch travel", not os.path.exists(path),
              path)
    check("no temporary file left",
          not any(n.endswith(".tmp") for n in os.listdir(output)),
          str(sorted(os.listdir(output))))


if __name__ == "__main__":
    main(sys.argv[1])
    sys.exit(1 if failures else 0)
