#!/usr/bin/env python3
"""The reference study's proposed anisotropy factor i_alpha, fitted from a sweep's table
(docs/footing-study.md, "The anisotropy factor"; results in bench/results/anisotropy_factor/).

The bearing capacity of a strip footing on bedded sand is written q(alpha) = i_alpha q(0), with
alpha the bedding angle. Two forms are fitted by least squares to q(alpha)/q(0) of the bedding
series (vertical load, Dr 85.6 %: cases V85.6, bedding_20, bedding_45, bedding_70, bedding_90):
  sin2:      i_alpha = 1 - a sin^2(alpha)                      (one parameter: a = 1 - q_H/q_V)
  sin2+mid:  i_alpha = 1 - a sin^2(alpha) - c sin^2(2 alpha)   (a bump or dip between 0 and 90)
sin^2 is the lowest even, 180-degree-periodic form that is flat at 0 and 90 deg (a bedding and
its mirror image carry the same); the second term tests whether the middle angles need more.
a at each Kimura density comes from the V-H pairs (V85.6-H86.7, V75.1-H76.5, V64.6-H61.0), with
q_V interpolated in ln q linearly in Dr to the H test's density (the pairs differ by 1.1-3.6
points of Dr). The uncertainty: every q moved uniformly within the table's band for q_ult (the
sweep's 'bands', a full spread; +-15 % at the recorded study's 0.09 m cells) in 4000 draws, the
2.5-97.5 % range of the fitted values; and the fit's own standard error from its residuals.

  python3 studies/anisotropy_factor.py [--sweep DIR] [--description FILE] [--out DIR]
Writes OUT/factor.csv (one row per fitted quantity), OUT/factor.json (the same with the inputs)
and OUT/factor.png.
"""
import argparse
import csv
import json
import math
import os
import random
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BEDDING = [("V85.6", 0.0), ("bedding_20", 20.0), ("bedding_45", 45.0), ("bedding_70", 70.0), ("bedding_90", 90.0)]
PAIRS = [("V85.6", "H86.7"), ("V75.1", "H76.5"), ("V64.6", "H61.0")]
KIMURA_DENSE = ("V85.6", 1952.7, "H86.7", 1733.8)  # data/lab/kimura_1985/tests_meta.csv, q_peak_kPa
DRAWS = 4000


def fit(s, t, r):
    """Least squares of 1 - r = a s (+ c t when t is given): returns (a, c, rms)."""
    y = [1.0 - v for v in r]
    if t is None:
        a = sum(si * yi for si, yi in zip(s, y)) / sum(si * si for si in s)
        c = 0.0
    else:
        sss, stt, sst = sum(x * x for x in s), sum(x * x for x in t), sum(x * z for x, z in zip(s, t))
        sy, ty = sum(x * v for x, v in zip(s, y)), sum(x * v for x, v in zip(t, y))
        det = sss * stt - sst * sst
        a, c = (sy * stt - ty * sst) / det, (ty * sss - sy * sst) / det
    res = [yi - a * si - c * (t[k] if t else 0.0) for k, (si, yi) in enumerate(zip(s, y))]
    return a, c, math.sqrt(sum(v * v for v in res) / len(res))


def standard_errors(s, t, r):
    """The fit's standard errors of a (and c) from its residuals (n - p degrees of freedom)."""
    a, c, rms = fit(s, t, r)
    n, p = len(s), 1 if t is None else 2
    sigma2 = rms * rms * n / max(1, n - p)
    if t is None:
        return math.sqrt(sigma2 / sum(x * x for x in s)), None
    sss, stt, sst = sum(x * x for x in s), sum(x * x for x in t), sum(x * z for x, z in zip(s, t))
    det = sss * stt - sst * sst
    return math.sqrt(sigma2 * stt / det), math.sqrt(sigma2 * sss / det)


def a_of_pair(q, dr, v, h, v_series):
    """1 - q_H/q_V with q_V at the H test's density (ln q_V linear in Dr between the V tests)."""
    pts = sorted((dr[n], math.log(q[n])) for n in v_series)
    x = dr[h]
    (x0, y0), (x1, y1) = (pts[0], pts[1]) if x <= pts[1][0] else (pts[-2], pts[-1])
    for k in range(len(pts) - 1):
        if pts[k][0] <= x <= pts[k + 1][0]:
            (x0, y0), (x1, y1) = pts[k], pts[k + 1]
    q_v = math.exp(y0 + (y1 - y0) * (x - x0) / (x1 - x0))
    return 1.0 - q[h] / q_v, 1.0 - q[h] / q[v]


def percentile(v, p):
    v = sorted(v)
    return v[min(len(v) - 1, max(0, int(round(p * (len(v) - 1)))))]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sweep", default=os.path.join(ROOT, "data/sweeps/recorded/reference_study_local_0.09m"))
    ap.add_argument("--description", default=os.path.join(ROOT, "data/sweeps/reference_study.json"))
    ap.add_argument("--out", default=os.path.join(ROOT, "bench/results/anisotropy_factor"))
    args = ap.parse_args()
    try:
        with open(os.path.join(args.sweep, "table.json")) as f:
            rows = {r["case"]: r for r in json.load(f)["cases"]}
        with open(args.description) as f:
            bands = {b["column"]: b for b in json.load(f).get("bands", [])}
    except (OSError, ValueError, KeyError) as e:
        sys.exit("anisotropy_factor.py: cannot read the sweep: %s" % e)
    need = [n for n, _ in BEDDING] + [n for p in PAIRS for n in p]
    missing = [n for n in need if n not in rows or rows[n].get("status") != "done" or rows[n].get("q_ult_kPa") is None]
    if missing:
        sys.exit("anisotropy_factor.py: cases not done in %s: %s" % (args.sweep, ", ".join(missing)))
    band = bands.get("q_ult_kPa", {}).get("relative", 0.0)
    q = {n: float(rows[n]["q_ult_kPa"]) for n in need}
    dr = {n: float(rows[n]["relative_density_pct"]) for n in need}
    alpha = [a for _, a in BEDDING]
    s = [math.sin(math.radians(a)) ** 2 for a in alpha]
    t = [math.sin(math.radians(2 * a)) ** 2 for a in alpha]

    def fits(qq):
        r = [qq[n] / qq["V85.6"] for n, _ in BEDDING]
        a1, _, rms1 = fit(s, None, r)
        a2, c2, rms2 = fit(s, t, r)
        pairs = [a_of_pair(qq, dr, v, h, [p[0] for p in PAIRS])[0] for v, h in PAIRS]
        return {"a_sin2": a1, "rms_sin2": rms1, "a_sin2_mid": a2, "c_sin2_mid": c2, "rms_sin2_mid": rms2,
                **{"a_pair_%s_%s" % (v, h): x for (v, h), x in zip(PAIRS, pairs)}}

    best = fits(q)
    rng = random.Random(1985)
    draws = []
    for _ in range(DRAWS):
        draws.append(fits({n: v * (1.0 + band * (rng.random() - 0.5)) for n, v in q.items()}))
    r0 = [q[n] / q["V85.6"] for n, _ in BEDDING]
    se1, _ = standard_errors(s, None, r0)
    se2a, se2c = standard_errors(s, t, r0)
    se = {"a_sin2": se1, "a_sin2_mid": se2a, "c_sin2_mid": se2c}
    centrifuge_a = 1.0 - KIMURA_DENSE[3] / KIMURA_DENSE[1]
    what = {
        "a_sin2": "a of i = 1 - a sin^2(alpha), bedding series at Dr 85.6 %",
        "rms_sin2": "its residual in q(alpha)/q(0)",
        "a_sin2_mid": "a of i = 1 - a sin^2(alpha) - c sin^2(2 alpha)",
        "c_sin2_mid": "c of the same",
        "rms_sin2_mid": "its residual in q(alpha)/q(0)",
    }
    for v, h in PAIRS:
        inside = min(dr[p[0]] for p in PAIRS) <= dr[h] <= max(dr[p[0]] for p in PAIRS)
        what["a_pair_%s_%s" % (v, h)] = "1 - q_%s/q_V at Dr %.1f %% (q_V %s from the V series)" % (
            h, dr[h], "interpolated" if inside else "extrapolated")
    os.makedirs(args.out, exist_ok=True)
    out_rows = []
    for k, v in best.items():
        vals = [d[k] for d in draws]
        out_rows.append({"quantity": k, "value": round(v, 4), "band_low": round(percentile(vals, 0.025), 4),
                         "band_high": round(percentile(vals, 0.975), 4),
                         "fit_standard_error": None if se.get(k) is None else round(se[k], 4), "meaning": what[k]})
    out_rows.append({"quantity": "a_centrifuge_dense", "value": round(centrifuge_a, 4), "band_low": None, "band_high": None,
                     "fit_standard_error": None,
                     "meaning": "1 - q_H86.7/q_V85.6 measured by Kimura et al. (1985): %.1f / %.1f kPa" % (KIMURA_DENSE[3], KIMURA_DENSE[1])})
    for (v, h) in PAIRS:
        out_rows.append({"quantity": "a_raw_%s_%s" % (v, h), "value": round(a_of_pair(q, dr, v, h, [p[0] for p in PAIRS])[1], 4),
                         "band_low": None, "band_high": None, "fit_standard_error": None,
                         "meaning": "1 - q_H/q_V as the pair stands, without the density interpolation"})
    with open(os.path.join(args.out, "factor.csv.tmp"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(out_rows[0].keys()))
        w.writeheader()
        w.writerows(out_rows)
    os.replace(os.path.join(args.out, "factor.csv.tmp"), os.path.join(args.out, "factor.csv"))
    doc = {"sweep": os.path.relpath(args.sweep, ROOT), "band_q_ult_relative": band, "draws": DRAWS,
           "q_ult_kPa": q, "relative_density_pct": dr, "bedding_series": [{"case": n, "alpha_deg": a, "q_over_q0": q[n] / q["V85.6"]} for n, a in BEDDING],
           "fits": out_rows}
    with open(os.path.join(args.out, "factor.json.tmp"), "w") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")
    os.replace(os.path.join(args.out, "factor.json.tmp"), os.path.join(args.out, "factor.json"))
    plot(args.out, BEDDING, q, band, best, dr, centrifuge_a)
    for r in out_rows:
        lo, hi = r["band_low"], r["band_high"]
        print("%-26s %8.4f %s  %s" % (r["quantity"], r["value"], "" if lo is None else "[%7.4f, %7.4f]" % (lo, hi), r["meaning"]))


def plot(out, bedding, q, band, best, dr, centrifuge_a):
    """factor.png: q(alpha)/q(0) with its band and the two fitted forms; a against Dr."""
    pts = "\n".join("%g %g %g" % (a, q[n] / q["V85.6"], band * q[n] / q["V85.6"] / 2.0) for n, a in bedding)
    pairs = "\n".join("%g %g" % (dr[h], best["a_pair_%s_%s" % (v, h)]) for v, h in PAIRS)
    lines = [
        "set terminal pngcairo size 1200,500 font 'DejaVu Sans,11' noenhanced",
        "set output '%s'" % os.path.join(out, "factor.png").replace("'", "''"),
        "set multiplot layout 1,2",
        "set title 'Bedding series (vertical load, Dr 85.6 %): q(α)/q(0) with the q_ult band'",
        "set xlabel 'bedding angle α [°]'", "set ylabel 'i_α = q(α)/q(0) [-]'", "set grid", "set key bottom left",
        "set xrange [-5:95]",
        "a1 = %.6g; a2 = %.6g; c2 = %.6g" % (best["a_sin2"], best["a_sin2_mid"], best["c_sin2_mid"]),
        "plot '-' using 1:2:3 with yerrorbars pt 7 title 'MPM (recorded study)', "
        + "1 - a1*sin(x*pi/180)**2 lw 2 title sprintf('1 %+.3f sin²α', -a1), "
        + "1 - a2*sin(x*pi/180)**2 - c2*sin(2*x*pi/180)**2 lw 2 dt 2 title sprintf('1 %+.3f sin²α %+.3f sin²2α', -a2, -c2), "
        + "1 - {0:.6g}*sin(x*pi/180)**2 lw 2 lc rgb 'black' dt 3 title 'centrifuge dense pair: 1 - {0:.3f} sin²α'".format(centrifuge_a),
        pts, "e",
        "set title 'a = 1 - q_H/q_V from the V-H pairs'", "set xlabel 'relative density Dr [%]'", "set ylabel 'a [-]'",
        "set xrange [55:95]", "set key top left",
        "plot '-' using 1:2 with linespoints pt 7 lw 2 title 'MPM (recorded study)', '-' using 1:2 with points pt 5 ps 1.5 lc rgb 'black' title 'Kimura et al. (1985), dense pair'",
        pairs, "e", "86.7 %g" % centrifuge_a, "e",
        "unset multiplot",
    ]
    subprocess.run(["gnuplot"], input="\n".join(lines), text=True, check=False)


if __name__ == "__main__":
    main()
