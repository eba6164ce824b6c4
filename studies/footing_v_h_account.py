#!/usr/bin/env python3
"""What puts H over V: one particle under each Kimura footing replayed at the element level, and
the laboratory tests that would tell the model's account from the centrifuge's (issue 77 item 3;
docs/footing-study.md, "What puts H over V").

For the particle PARTICLE (default B, under the footing's half width) of the V and the H run, the
recorded strain path is replayed by acst_element as run and with the start fabric turned 90 deg
(bedding 0 <-> 90), as studies/footing_particle_replay.py does; the replay gives the path's
stress, fabric (A, |F|) and state parameters (psi, zeta = psi - e_A (A - 1)) along the deviatoric
strain e_q. Then the element tests that carry one bedding against the other past the peak:
  - Lam & Tatsuoka (1988) Fig. 5(a), drained triaxial at 98 kPa with the bedding at 0 and 90 deg,
    the model against the data (the bundled scenes data/scenes/element/lab_lt88_fig5a_w*);
  - plane-strain compression at sigma_3 = SIGMA3 of the V particle's start void ratio, bedding 0
    and 90 deg, to 20 % axial strain (the footing's plane strain; no data).
Writes OUT/account.json (the particles' state at their footing's peak and at e_q 3, 6 and 10 %;
the bedding gaps (q_0 - q_90) / q_0 of model and data at eps_a 3, 6, 10 and 12 %; the strain at
which the model's bedding-90 specimen overtakes the bedding-0 one), OUT/account.png, and the
scenes and element outputs in OUT/work/.

  python3 studies/footing_v_h_account.py --v data/sweeps/recorded/reference_study/kept/V85.6 \\
      --h data/sweeps/recorded/reference_study/kept/H86.7 --out bench/results/footing_v_h_account
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

from footing_common import ROOT, gp_quoted, value_at
from footing_particle_replay import FABRIC, STRAINS, STRESSES, STEM, p_q, read_rows, scene

LAB = os.path.join(ROOT, "data", "scenes", "element")
LT88 = {0: "lab_lt88_fig5a_w00_hw1p0", 90: "lab_lt88_fig5a_w90_hw1p0"}
GAP_STRAINS = (3.0, 6.0, 10.0, 12.0)
EQ_MARKS = (3.0, 6.0, 10.0)
STATE = ("p_kPa", "q_kPa", "stress_ratio", "void_ratio", "psi", "zeta", "A", "F_norm")


def run(tool, scenes, out):
    done = subprocess.run([tool, "--quiet", "--no-plot", "--output", out] + scenes)
    if done.returncode != 0:
        sys.exit(f"acst_element failed ({done.returncode}) on {scenes}")


def replay_particle(a, label, run_dir, material, work):
    """Replays the history as run and turned; returns (history rows, {variant: element rows}, S_ult/B)."""
    history = os.path.join(run_dir, f"particle_{a.particle}.csv")
    if not os.path.exists(history):
        sys.exit(f"--{label.lower()}: no {history}")
    with open(os.path.join(run_dir, "summary.json")) as f:
        s_ult = json.load(f)["S_ult_over_B"]
    rows = read_rows(history)
    name = f"{label}_{a.particle}"
    path_file = os.path.join(work, name + "_path.csv")
    with open(path_file, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(STRAINS)
        w.writerows([repr(r[k]) for k in STRAINS] for r in rows[1:])
    scenes = []
    for v in ("replay", "turned"):
        path = os.path.join(work, f"{name}_{v}.json")
        with open(path, "w") as f:
            json.dump(scene(material, rows, os.path.abspath(path_file), work, name, v), f, indent=1)
        scenes.append(path)
    run(a.tool, scenes, work)
    return rows, {v: read_rows(os.path.join(work, f"{name}_{v}.csv")) for v in ("replay", "turned")}, s_ult


def state_at(rows, key, value):
    """The STATE columns of the first row whose `key` reaches `value` (None if none does)."""
    for r in rows:
        if r[key] >= value:
            return {k: round(r[k], 4) for k in STATE} | {key: round(r[key], 3)}
    return None


def lab_curve(path):
    """(eps_a, stress ratio) of a digitised file: the rows that carry a stress ratio."""
    rows = read_rows(path)
    pts = [(r["eps_a_pct"], r["stress_ratio"]) for r in rows if isinstance(r.get("stress_ratio"), float)]
    return [p[0] for p in pts], [p[1] for p in pts]


def element_tests(a, work):
    """The LT88 scenes (model and data) and the plane-strain pair; returns their curves."""
    scenes, lab_data = [], {}
    for angle, stem in LT88.items():
        with open(os.path.join(LAB, stem + ".json")) as f:
            s = json.load(f)
        s["material"]["file"] = os.path.abspath(a.material)
        s["lab_data"] = lab_data[angle] = os.path.normpath(os.path.join(LAB, s["lab_data"]))
        path = os.path.join(work, stem + ".json")
        with open(path, "w") as f:
            json.dump(s, f, indent=1)
        scenes.append(path)
    for angle in (0, 90):
        s = {"description": f"plane-strain compression, sigma_3 {a.sigma3:g} kPa, e0 {a.e0:g}, bedding {angle} deg",
             "material": {"file": os.path.abspath(a.material)},
             "initial_state": {"confining_pressure": a.sigma3, "void_ratio": a.e0, "bedding_angle_deg": angle},
             "steps": [{"preset": "plane_strain_compression", "axial_strain_pct": 20, "increments": 2000}]}
        path = os.path.join(work, f"psc_b{angle:02d}.json")
        with open(path, "w") as f:
            json.dump(s, f, indent=1)
        scenes.append(path)
    run(a.tool, scenes, work)
    curves = {}
    for angle, stem in LT88.items():
        m = read_rows(os.path.join(work, stem + ".csv"))
        curves[f"lt88_model_{angle}"] = ([r["eps_a_pct"] for r in m], [r["sigma_11_kPa"] / r["sigma_33_kPa"] for r in m])
        curves[f"lt88_data_{angle}"] = lab_curve(lab_data[angle])
    for angle in (0, 90):
        m = read_rows(os.path.join(work, f"psc_b{angle:02d}.csv"))
        curves[f"psc_{angle}"] = ([r["eps_a_pct"] for r in m], [r["q_kPa"] for r in m])
    return curves


def gaps(curves, key0, key90):
    out = {}
    for x in GAP_STRAINS:
        y0 = value_at(*curves[key0], x)
        y90 = value_at(*curves[key90], x)
        out[f"{x:g}"] = None if math.isnan(y0) or math.isnan(y90) else round((y0 - y90) / y0, 4)
    return out


def overtaking(curves, key0, key90):
    """The first strain past the bedding-0 curve's peak where bedding 90 carries more (None if never)."""
    x0, y0 = curves[key0]
    peak = x0[max(range(len(y0)), key=y0.__getitem__)]
    x90, y90 = curves[key90]
    for x, y in zip(x90, y90):
        ref = value_at(x0, y0, x)
        if x > peak and not math.isnan(ref) and y > ref:
            return round(x, 2)
    return None


def plot(out, work, particles, curves):
    def dat(name, pairs):
        path = os.path.join(work, name + ".dat")
        with open(path, "w", newline="") as f:
            csv.writer(f).writerows(pairs)
        return gp_quoted(path)

    colour = {"V": "#1f77b4", "H": "#d62728"}
    s = ["set terminal pngcairo size 1500,900 font ',9'", f"set output {gp_quoted(os.path.join(out, 'account.png'))}",
         "set multiplot layout 2,3 title 'What puts H over V: a particle under each footing, replayed, and the tests that would tell'",
         "set datafile separator ','", "set grid", "set key top left", "set termoption noenhanced"]
    panels = [("p [kPa]", "q [kPa]", "stress path (MPM black, replay colour)"),
              ("e_q [%]", "A (fabric against loading)", "fabric: A, and |F| dashed"),
              ("e_q [%]", "state parameter", "psi solid, zeta dashed")]
    for i, (xl, yl, title) in enumerate(panels):
        s += [f"set xlabel '{xl}'", f"set ylabel '{yl}'", f"set title '{title}'"]
        curves_ = []
        for label, (rows, reps, _) in particles.items():
            r = reps["replay"]
            c = colour[label]
            if i == 0:
                curves_.append(f"{dat(label + '_mpm_pq', [(p_q([h[k] for k in STRESSES])) for h in rows])} using 1:2 with lines lc rgb 'black' notitle")
                curves_.append(f"{dat(label + '_pq', [(g['p_kPa'], g['q_kPa']) for g in r])} using 1:2 with lines lw 2 lc rgb '{c}' title '{label} particle'")
            elif i == 1:
                curves_.append(f"{dat(label + '_A', [(g['e_q_pct'], g['A'], g['F_norm']) for g in r])} using 1:2 with lines lw 2 lc rgb '{c}' title '{label}: A', '' using 1:3 with lines dt 2 lc rgb '{c}' title '{label}: |F|'")
            else:
                curves_.append(f"{dat(label + '_state', [(g['e_q_pct'], g['psi'], g['zeta']) for g in r])} using 1:2 with lines lw 2 lc rgb '{c}' title '{label}: psi', '' using 1:3 with lines dt 2 lc rgb '{c}' title '{label}: zeta'")
        s.append("plot " + ", ".join(curves_))
    s += ["set xlabel 'S/B'", "set ylabel 'q [kPa]'", "set title 'q of the particle: replay as run and with the fabric turned 90 deg'"]
    curves_ = []
    for label, (rows, reps, _) in particles.items():
        c = colour[label]
        for v, dash in (("replay", 1), ("turned", 2)):
            pts = [(h["S_over_B"], g["q_kPa"]) for h, g in zip(rows, reps[v])]
            curves_.append(f"{dat(label + '_' + v + '_q', pts)} using 1:2 with lines dt {dash} lw 2 lc rgb '{c}' title '{label} {v}'")
    s += ["set key top right", "plot " + ", ".join(curves_)]
    s += ["set xlabel 'eps_a [%]'", "set ylabel 'sigma_1 / sigma_3'", "set title 'Lam & Tatsuoka 1988, triaxial at 98 kPa: model (lines), data (points)'"]
    curves_ = []
    for angle, c in ((0, "#1f77b4"), (90, "#d62728")):
        curves_.append(f"{dat(f'lt88_model_{angle}', zip(*curves[f'lt88_model_{angle}']))} using 1:2 with lines lw 2 lc rgb '{c}' title 'model, bedding {angle}'")
        curves_.append(f"{dat(f'lt88_data_{angle}', zip(*curves[f'lt88_data_{angle}']))} using 1:2 with points pt 7 ps 0.5 lc rgb '{c}' title 'data, bedding {angle}'")
    s += ["set xrange [0:20]", "set key bottom right", "plot " + ", ".join(curves_)]
    s += ["set ylabel 'q [kPa]'", "set title 'plane-strain compression, the model at bedding 0 and 90'"]
    curves_ = [f"{dat(f'psc_{angle}', zip(*curves[f'psc_{angle}']))} using 1:2 with lines lw 2 lc rgb '{c}' title 'bedding {angle}'"
               for angle, c in ((0, "#1f77b4"), (90, "#d62728"))]
    s += ["plot " + ", ".join(curves_), "unset multiplot"]
    subprocess.run(["gnuplot"], input="\n".join(s) + "\n", text=True, check=False)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--v", required=True, help="kept folder of the V run (summary.json, particle_*.csv)")
    ap.add_argument("--h", required=True, help="kept folder of the H run")
    ap.add_argument("--particle", default="B")
    ap.add_argument("--material", default=os.path.join(ROOT, "data", "parameters", "toyoura_acst_calibrated.json"))
    ap.add_argument("--sigma3", type=float, default=200.0, help="plane-strain pair's confining stress [kPa]")
    ap.add_argument("--out", required=True)
    ap.add_argument("--tool", default=os.path.join(ROOT, "build", "driver", "acst_element"))
    a = ap.parse_args()
    if not STEM.match(a.particle):
        sys.exit(f"--particle {a.particle!r}: a plain stem (letters, digits, . _ -)")
    a.out = os.path.abspath(a.out)
    work = os.path.join(a.out, "work")
    os.makedirs(work, exist_ok=True)
    with open(a.material) as f:
        material = json.load(f)
    particles = {label: replay_particle(a, label, d, material, work) for label, d in (("V", a.v), ("H", a.h))}
    a.e0 = round(particles["V"][0][0]["void_ratio"], 4)
    curves = element_tests(a, work)
    summary = {"particle": a.particle, "material": os.path.relpath(a.material, ROOT), "particles": {}}
    for label, (rows, reps, s_ult) in particles.items():
        r = reps["replay"]
        at_peak = min(range(len(rows)), key=lambda i: abs(rows[i]["S_over_B"] - s_ult))
        summary["particles"][label] = {
            "start": {"x_m": rows[0]["x_m"], "y_m": rows[0]["y_m"]}, "footing_S_ult_over_B": s_ult,
            "at_footing_peak": {k: round(r[at_peak][k], 4) for k in STATE} | {"e_q_pct": round(r[at_peak]["e_q_pct"], 3)},
            "q_at_peak_kPa": {"mpm": round(p_q([rows[at_peak][k] for k in STRESSES])[1], 1),
                              "replay": round(r[at_peak]["q_kPa"], 1), "turned": round(reps["turned"][at_peak]["q_kPa"], 1)},
            "at_e_q_pct": {f"{x:g}": state_at(r, "e_q_pct", x) for x in EQ_MARKS}}
    summary["bedding_gap"] = {"lt88_triaxial_98kPa": {"model": gaps(curves, "lt88_model_0", "lt88_model_90"),
                                                      "data": gaps(curves, "lt88_data_0", "lt88_data_90")},
                              f"plane_strain_{a.sigma3:g}kPa_e{a.e0:g}": {"model": gaps(curves, "psc_0", "psc_90")}}
    summary["bedding_90_overtakes_at_eps_a_pct"] = {"lt88_model": overtaking(curves, "lt88_model_0", "lt88_model_90"),
                                                    "lt88_data": overtaking(curves, "lt88_data_0", "lt88_data_90"),
                                                    "plane_strain_model": overtaking(curves, "psc_0", "psc_90")}
    with open(os.path.join(a.out, "account.json"), "w") as f:
        json.dump(summary, f, indent=1)
    print(json.dumps(summary, indent=1))
    plot(a.out, work, particles, curves)
    return 0


if __name__ == "__main__":
    sys.exit(main())
