#!/usr/bin/env python3
"""Plane-strain biaxial compression of dense Toyoura sand in the MPM, local and regularised
(docs/footing-study.md, "The regularised biaxial test").

A W x H sample (default 0.8 x 1.6 m) on a rough base under a smooth rigid platen wider than the
sample, its sides under the confining pressure, an imperfection (a looser square at mid-height
on the left side) where the band starts. Each case runs acst_mpm to an axial strain and is
measured: the axial stress ratio sigma_1/sigma_3 against the axial strain, its peak, and the
shear band's thickness (the full width at half height of the shear-strain increment across the
band, between two axial strains after the peak).

  python3 studies/biaxial_band.py --out DIR [--threads 2] CASE ...
  CASE: h=0.025,l=0.05[,kernel=gauss|galavi_schweiger][,averaged=void_ratio_increments|void_ratio]
        [,m=1][,every=20][,weak=0.1][,lc=0.02][,kc=0.5]   (l=0: the local model; weak: the
        imperfection's side, m; lc, kc: micropolar rotations' length, m, and modulus ratio)
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

from footing_common import ROOT, gp_quoted
from footing_fields import read_vtp

WIDTH, HEIGHT, SIGMA3, DR = 0.8, 1.6, 100.0, 85.6
PLATEN_OVERHANG = 0.6  # the smooth platen is wider than the sample: the upper block slides along the band
BASE = "fixed"
WEAK = {"size": 0.1, "y": 0.5, "void_ratio_increase": 0.05}


def scene(case, speed, strain_to):
    h, l = case["h"], case["l"]
    e_dense = None  # from the relative density, through the material
    weak = float(case.get("weak", WEAK["size"]))  # the imperfection's side
    weak_lo, weak_hi = WEAK["y"], WEAK["y"] + weak
    base = {"material": "toyoura", "density": 1600, "particles_per_cell": 1, "bedding_angle_deg": 0}
    # The void ratio of Dr 85.6 % (e_max 0.977, e_min 0.597 of the delivered set): the weak square is looser.
    e0 = 0.977 - DR / 100.0 * (0.977 - 0.597)
    bodies = [dict(base, name="below", x_range=[0, WIDTH], y_range=[0, weak_lo], void_ratio=e0),
              dict(base, name="weak", x_range=[0, weak], y_range=[weak_lo, weak_hi],
                   void_ratio=e0 + WEAK["void_ratio_increase"]),
              dict(base, name="beside", x_range=[weak, WIDTH], y_range=[weak_lo, weak_hi], void_ratio=e0),
              dict(base, name="above", x_range=[0, WIDTH], y_range=[weak_hi, HEIGHT], void_ratio=e0)]
    s = {"name": case["name"],
         "description": "Plane-strain biaxial compression of dense Toyoura sand (studies/biaxial_band.py)",
         "grid": {"cell_size": h, "cells_above": 4, "cells_beside": int(math.ceil(0.3 / h))},
         "materials": {"toyoura": os.path.join(ROOT, "data", "parameters", "toyoura_acst_calibrated.json")},
         "bodies": bodies,
         "initial_stress": {"type": "isotropic", "p_kPa": SIGMA3},
         "walls": {"base": BASE, "sides": "none"},
         "confining_pressure_kPa": SIGMA3,
         "footing": {"width": WIDTH + PLATEN_OVERHANG, "centre_x": WIDTH / 2, "speed": speed, "interface": "smooth",
                     "ramp_S_over_B": 0.002},
         "solver": {"stress_update": "first", "threads": case.get("threads", 2)},
         "stop": {"S_over_B": strain_to * HEIGHT / (WIDTH + PLATEN_OVERHANG)},
         "output": {"vtk_every_S_over_B": 0.01 * HEIGHT / (WIDTH + PLATEN_OVERHANG), "contours_at_peak": False,
                    "checkpoint_every_s": 0}}
    if l > 0:
        s["regularisation"] = {"internal_length_m": l, "kernel": case.get("kernel", "gauss"),
                               "averaged": case.get("averaged", "void_ratio_increments"),
                               "over_nonlocal": float(case.get("m", 1.0)), "every_steps": int(case.get("every", 20))}
    if float(case.get("lc", 0)) > 0:
        s["micropolar"] = {"length_m": float(case["lc"]), "modulus_ratio": float(case.get("kc", 0.5))}
    return s


def curve(run_dir, record="load_settlement.csv"):
    """Axial strain (%) and sigma_1/sigma_3 (sigma_1 = V / W, V the platen's load) from the load record."""
    with open(os.path.join(run_dir, record)) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    eps = [100.0 * float(r["S_m"]) / HEIGHT for r in rows]
    ratio = [float(r["V_kN_per_m"]) / WIDTH / SIGMA3 for r in rows]
    return eps, ratio


def frame_at(run_dir, eps_pct):
    pvd = os.path.join(run_dir, "particles.pvd")
    import xml.etree.ElementTree as ET
    sets = [(float(d.get("timestep")), d.get("file")) for d in ET.parse(pvd).getroot().iter("DataSet")]
    with open(os.path.join(run_dir, "load_settlement.csv")) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    t = min(rows, key=lambda r: abs(100.0 * float(r["S_m"]) / HEIGHT - eps_pct))["time_s"]
    return os.path.join(run_dir, min(sets, key=lambda s: abs(s[0] - float(t)))[1])


def band(run_dir, eps_from, eps_to, h):
    """Band centre line, angle from the horizontal (deg) and thickness (m, FWHM of the shear-strain
    increment across it), from the frames at two axial strains."""
    x0, y0, f0 = read_vtp(frame_at(run_dir, eps_from), ["shear_strain"])
    x1, y1, f1 = read_vtp(frame_at(run_dir, eps_to), ["shear_strain"])
    dg = [b - a for a, b in zip(f0["shear_strain"], f1["shear_strain"])]
    top = max(dg)
    sel = [i for i in range(len(dg)) if dg[i] > 0.5 * top]
    w = [dg[i] for i in sel]
    mx = sum(x1[i] * wi for i, wi in zip(sel, w)) / sum(w)
    my = sum(y1[i] * wi for i, wi in zip(sel, w)) / sum(w)
    sxx = sum(wi * (x1[i] - mx) ** 2 for i, wi in zip(sel, w))
    syy = sum(wi * (y1[i] - my) ** 2 for i, wi in zip(sel, w))
    sxy = sum(wi * (x1[i] - mx) * (y1[i] - my) for i, wi in zip(sel, w))
    theta = 0.5 * math.atan2(2 * sxy, sxx - syy)  # the band's direction
    tx, ty = math.cos(theta), math.sin(theta)
    # Profile across the band, over its middle half (away from the sample's faces).
    along = [(x1[i] - mx) * tx + (y1[i] - my) * ty for i in range(len(dg))]
    across = [-(x1[i] - mx) * ty + (y1[i] - my) * tx for i in range(len(dg))]
    span = max(abs(along[i]) for i in sel)
    bins = {}
    step = h / 2
    for i in range(len(dg)):
        if abs(along[i]) <= 0.5 * span:
            bins.setdefault(math.floor(across[i] / step), []).append(dg[i])
    keys = sorted(bins)
    prof = [(step * (k + 0.5), sum(bins[k]) / len(bins[k])) for k in keys]
    peak = max(v for _, v in prof)
    k = max(range(len(prof)), key=lambda i: prof[i][1])
    def cross(direction):
        i = k
        while 0 <= i + direction < len(prof) and prof[i + direction][1] > 0.5 * peak:
            i += direction
        j = i + direction
        if not 0 <= j < len(prof):
            return prof[i][0]
        (a, va), (b, vb) = prof[i], prof[j]
        return a + (va - 0.5 * peak) / (va - vb) * (b - a)
    thickness = cross(1) - cross(-1)
    # The equivalent width (integral)^2 / integral of the square over the profile within three
    # half-widths of the peak, less the profile's median (the rest of the sample): w for a
    # top-hat of width w, 3.5 sigma for a Gaussian; less sensitive than the half-height width to
    # a ragged profile.
    base = sorted(v for _, v in prof)[len(prof) // 2]
    near = [max(v - base, 0.0) for x, v in prof if abs(x - prof[k][0]) <= 1.5 * thickness]
    equivalent = step * sum(near) ** 2 / sum(v * v for v in near)
    return {"angle_deg": round(math.degrees(theta) % 180.0, 1), "thickness_m": round(thickness, 4),
            "equivalent_width_m": round(equivalent, 4), "profile": prof, "peak_increment": peak}


def figure(out, title, runs):
    """OUT: sigma_1/sigma_3 against the axial strain and the band's profile, one line per run
    (label, run folder, profile CSV)."""
    lines = ["set terminal pngcairo size 1300,520 noenhanced", f"set output {gp_quoted(out)}", "set multiplot layout 1,2",
             "set grid", "set key top right", "set xlabel 'axial strain [%]'", "set ylabel 'sigma_1 / sigma_3'",
             f"set title {gp_quoted(title)}", "set yrange [0:8]"]
    plots, data = [], []
    for label, run_dir, _ in runs:
        eps, ratio = curve(run_dir)
        plots.append(f"'-' using 1:2 with lines lw 2 title {gp_quoted(label)}")
        data.append("\n".join(f"{e} {r}" for e, r in zip(eps, ratio)) + "\ne")
    lines += ["plot " + ", ".join(plots)] + data
    lines += ["set xlabel 'distance across the band [m]'", "set ylabel 'shear strain increment, 6 to 10 % axial strain'",
              "set title 'the band across its middle half'", "set yrange [*:*]", "set xrange [-0.3:0.3]"]
    plots, data = [], []
    for label, _, profile in runs:
        with open(profile) as f:
            rows = [r for r in csv.reader(f)][1:]
        plots.append(f"'-' using 1:2 with linespoints lw 2 pt 7 ps 0.5 title {gp_quoted(label)}")
        data.append("\n".join(f"{x} {v}" for x, v in rows) + "\ne")
    lines += ["plot " + ", ".join(plots)] + data + ["unset multiplot", ""]
    subprocess.run(["gnuplot"], input="\n".join(lines), text=True, check=False)


def parse_case(text, threads):
    c = {"threads": threads}
    for part in text.split(","):
        k, v = part.split("=", 1)
        if k in ("h", "l"):  # a number or a quotient (h=0.1/3: cells that tile the sample)
            a, _, b = v.partition("/")
            c[k + "_text"] = v.replace("/", "d")
            c[k] = float(a) / float(b) if b else float(a)
        else:
            c[k] = v
    tag = f"h{c['h_text']}_l{c['l_text']}" + (f"_{c['kernel']}" if "kernel" in c else "") + (
        f"_{c['averaged']}" if "averaged" in c else "") + (f"_m{c['m']}" if "m" in c else "") + (
        f"_every{c['every']}" if "every" in c else "") + (f"_weak{c['weak']}" if "weak" in c else "") + (
        f"_lc{c['lc']}" if "lc" in c else "") + (f"_kc{c['kc']}" if "kc" in c else "")
    c["name"] = "biaxial_" + tag.replace(".", "p")
    return c


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--speed", type=float, default=0.1, help="platen speed, m/s")
    ap.add_argument("--strain", type=float, default=0.12, help="axial strain to run to")
    ap.add_argument("--band-from", type=float, default=6.0, help="axial strain (%%) of the first frame of the band increment")
    ap.add_argument("--band-to", type=float, default=10.0, help="axial strain (%%) of the second")
    ap.add_argument("--tool", default=os.path.join(ROOT, "build", "mpm_adapter", "acst_mpm"))
    ap.add_argument("--analyse-only", action="store_true")
    ap.add_argument("--size", type=float, default=1.0, help="the sample's width and height times 0.8 x 1.6 m")
    ap.add_argument("--figure", default="", help="also draw the cases into this PNG (its title: --title)")
    ap.add_argument("--title", default="biaxial compression, dense Toyoura, sigma_3 100 kPa")
    ap.add_argument("cases", nargs="+")
    a = ap.parse_args()
    global WIDTH, HEIGHT
    WIDTH, HEIGHT = 0.8 * a.size, 1.6 * a.size
    os.makedirs(a.out, exist_ok=True)
    results = []
    for text in a.cases:
        c = parse_case(text, a.threads)
        run_dir = os.path.join(a.out, c["name"])
        if not a.analyse_only:
            path = os.path.join(a.out, c["name"] + ".json")
            with open(path, "w") as f:
                json.dump(scene(c, a.speed, a.strain), f, indent=1)
            run = subprocess.run([a.tool, "--quiet", "--no-plot", "--output", run_dir, path], capture_output=True, text=True)
            if run.returncode != 0:  # recorded, not hidden: a formulation that loses the run is a result
                failed = os.path.join(run_dir, "load_settlement.failed.csv")
                eps_f = curve(run_dir, "load_settlement.failed.csv")[0][-1] if os.path.exists(failed) else float("nan")
                r = {"case": c["name"], "h_m": c["h"], "l_m": c["l"], "failed_at_eps_pct": round(eps_f, 2),
                     "message": run.stderr.strip().splitlines()[0] if run.stderr.strip() else f"exit {run.returncode}"}
                print(json.dumps(r))
                sys.stdout.flush()
                continue
        eps, ratio = curve(run_dir)
        k = max(range(len(ratio)), key=lambda i: ratio[i])
        b = band(run_dir, a.band_from, a.band_to, c["h"])
        with open(os.path.join(run_dir, "summary.json")) as f:
            wall = json.load(f)["wall_s"]
        r = {"case": c["name"], "h_m": c["h"], "l_m": c["l"], "kernel": c.get("kernel", "gauss" if c["l"] > 0 else ""),
             "averaged": c.get("averaged", "void_ratio_increments" if c["l"] > 0 else ""),
             "over_nonlocal": float(c.get("m", 1.0)) if c["l"] > 0 else "",
             "micropolar_length_m": float(c.get("lc", 0)), "micropolar_modulus_ratio": float(c.get("kc", 0.5)) if "lc" in c else "",
             "peak_ratio": round(ratio[k], 3), "eps_peak_pct": round(eps[k], 2),
             "ratio_at_8pct": round(next((ratio[i] for i in range(len(eps)) if eps[i] >= 8.0), float("nan")), 3),
             "ratio_at_12pct": round(ratio[-1], 3), "band_angle_deg": b["angle_deg"], "band_thickness_m": b["thickness_m"],
             "band_equivalent_width_m": b["equivalent_width_m"],
             "wall_s": round(wall, 1)}
        print(json.dumps(r))
        sys.stdout.flush()
        results.append(r)
        with open(os.path.join(a.out, c["name"] + "_profile.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["across_m", "shear_strain_increment"])
            w.writerows(b["profile"])
    if a.figure:
        figure(a.figure, a.title, [(r["case"].replace("biaxial_", ""), os.path.join(a.out, r["case"]),
                                    os.path.join(a.out, r["case"] + "_profile.csv")) for r in results if "peak_ratio" in r])
    fields = list(results[0].keys())
    with open(os.path.join(a.out, "biaxial.csv"), "a", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        if f.tell() == 0:
            w.writeheader()
        w.writerows(results)


if __name__ == "__main__":
    main()
