#!/usr/bin/env python3
"""The initial slope of the Kimura footing curves against an elastic estimate (docs/footing-study.md, "The initial slope").

For each load level q (kPa) it prints the settlement S/B at which a curve first reaches q and the
secant q / (S/B), for the MPM runs given and for Kimura et al.'s (1985) centrifuge curves. The
elastic estimate integrates dq/d(S/B) = K_z(G) for a rigid strip on an elastic stratum over a
rigid base (Gazetas 1991: K_z = 0.73 G / (1 - nu) (1 + 3.5 b / H) per metre, b = B/2 the
half-width, H the layer depth), with G taken at depth B/2 under the centre, where the mean
stress is the geostatic one plus the elastic strip solution's (sigma_x + sigma_z = 2 q alpha / pi,
alpha the angle the footing subtends; sigma_zz = nu (sigma_x + sigma_z) in plane strain). Two shear
moduli:
  - the model's: G = G0 pa (2.97 - e)^2 / (1 + e) sqrt(p / pa) with the calibrated set's G0, nu;
  - small-strain resonant-column / torsional values for Toyoura sand, Iwasaki, Tatsuoka & Takagi
    (1978), Soils and Foundations 18(1): G = 900 (2.17 - e)^2 / (1 + e) p^0.4 in kgf/cm2
    (p in kgf/cm2), an upper bound: the footing strains the sand far beyond 1e-5.

  python3 studies/footing_initial_slope.py [--run NAME=load_settlement.csv ...]
"""
import argparse
import json
import math
import os

from footing_common import read_curve

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PA = 101.325  # kPa, the model's reference pressure
KGF_CM2 = 98.0665  # kPa
LEVELS = (250.0, 500.0, 1000.0)
B, LAYER, K0, SURCHARGE, G_ACC = 0.9, 6.3, 0.4, 1.0, 9.8
# Kimura's tests (void ratios assumed from D_r by the transcriber, data/lab/kimura_1985) and the
# scenes' densities (kg/m3).
TESTS = {"V85.6": (0.6517, 1600.0), "H86.7": (0.6475, 1603.0)}


def first_reach(xs, ys, q):
    for i in range(1, len(xs)):
        if ys[i - 1] < q <= ys[i]:
            t = (q - ys[i - 1]) / (ys[i] - ys[i - 1])
            return xs[i - 1] + t * (xs[i] - xs[i - 1])
    return math.nan


def mean_stress(q, rho, nu):
    z = 0.5 * B
    sigma_v0 = SURCHARGE + rho * G_ACC * z / 1000.0
    p0 = (1 + 2 * K0) / 3 * sigma_v0
    alpha = 2 * math.atan(0.5 * B / z)
    in_plane = 2 * q * alpha / math.pi
    return p0 + (1 + nu) * in_plane / 3


def g_model(e, p, g0):
    return g0 * PA * (2.97 - e) ** 2 / (1 + e) * math.sqrt(p / PA)


def g_iwasaki(e, p):
    return 900 * (2.17 - e) ** 2 / (1 + e) * (p / KGF_CM2) ** 0.4 * KGF_CM2


def elastic_reach(q_target, shear_modulus, nu):
    """S/B where the load reaches q_target, integrating d(S/B) = dq / K_z(G(q))."""
    steps, s = 2000, 0.0
    for i in range(steps):
        q = (i + 0.5) * q_target / steps
        k = 0.73 * shear_modulus(q) / (1 - nu) * (1 + 3.5 * 0.5 * B / LAYER)
        s += q_target / steps / k
    return s


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--run", action="append", default=[], help="TEST=path/to/load_settlement.csv (TEST: V85.6 or H86.7)")
    ap.add_argument("--parameters", default=os.path.join(ROOT, "data", "parameters", "toyoura_acst_calibrated.json"))
    a = ap.parse_args()
    with open(a.parameters) as f:
        par = json.load(f)["parameters"]
    g0, nu = par["G0"], par["nu"]
    header = "curve".ljust(58) + "".join(f"  S/B at {q:.0f} kPa (secant)" for q in LEVELS)
    print(header)
    rows = []
    for test, (e, rho) in TESTS.items():
        rows.append((f"{test} Kimura et al. (1985)", read_curve(os.path.join(ROOT, "data", "lab", "kimura_1985", test + ".csv"))))
        for r in a.run:
            name, path = r.split("=", 1)
            if name == test:
                rows.append((f"{test} MPM {os.path.basename(os.path.dirname(os.path.abspath(path)))}", read_curve(path)))
        for label, g in ((f"model G (G0 {g0:g}, nu {nu:g})", lambda q: g_model(e, mean_stress(q, rho, nu), g0)),
                         ("Iwasaki et al. (1978) G_max, same nu", lambda q: g_iwasaki(e, mean_stress(q, rho, nu)))):
            ss = [elastic_reach(q, g, nu) for q in LEVELS]
            rows.append((f"{test} elastic strip, {label}", ([0.0] + ss, [0.0] + list(LEVELS))))
    for label, (xs, ys) in rows:
        cells = ""
        for q in LEVELS:
            s = first_reach(xs, ys, q)
            cells += f"  {s:10.4f} ({q / s if s > 0 else math.nan:8.0f})" if math.isfinite(s) else "  " + "-".rjust(21)
        print(label.ljust(58) + cells)
    print(f"G at depth B/2 under q = 500 kPa: model {g_model(0.65, mean_stress(500, 1600, nu), g0) / 1000:.1f} MPa, "
          f"Iwasaki et al. {g_iwasaki(0.65, mean_stress(500, 1600, nu)) / 1000:.1f} MPa (e 0.65)")


if __name__ == "__main__":
    main()
