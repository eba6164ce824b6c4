#!/usr/bin/env python3
"""Replays footing particles' strain histories in the element driver (docs/mpm.md, "Particle histories").

For every particle_NAME.csv of each run (written by acst_mpm for output/particle_histories), the
recorded strain path (in the particle's material frame, as acst_element reads it) is pushed
through the material from the recorded start three times:
  replay   the material as in the run;
  turned   its start fabric turned 90 deg about the out-of-plane axis (bedding 0 <-> 90);
  kf0      fabric evolution off (k_f = 0).
Writes OUT/replays.csv (per particle: q of the MPM and of each replay at the footing's peak and
their maxima up to S/B 0.2, the RMS gap of the replay to the MPM's stresses over the whole run,
the rotation at the peak) and OUT/<run>_replays.png (q against S/B for each particle).

  python3 studies/footing_particle_replay.py --run V85.6=DIR --run H86.7=DIR \\
      --material data/parameters/toyoura_acst_calibrated.json --out DIR
"""
import argparse
import csv
import glob
import json
import math
import os
import re
import subprocess
import sys

from footing_common import gp_quoted

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STEM = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9._-]{0,99}$")
STRAINS = ["eps_11_pct", "eps_22_pct", "eps_33_pct", "gamma_12_pct", "gamma_13_pct", "gamma_23_pct"]
STRESSES = ["sigma_11_kPa", "sigma_22_kPa", "sigma_33_kPa", "sigma_12_kPa", "sigma_13_kPa", "sigma_23_kPa"]
FABRIC = ["F11", "F22", "F33", "F12", "F13", "F23"]
VARIANTS = ("replay", "turned", "kf0")
EARLY = 0.2  # S/B up to which the table's maxima are taken: past the peak, before the top row unloads


def number(text):
    try:
        return float(text)
    except ValueError:
        return text


def read_rows(path):
    """The rows of a CSV with '#' comment lines: numbers where they are numbers."""
    with open(path) as f:
        return [{k: number(v) for k, v in r.items()} for r in csv.DictReader(l for l in f if not l.startswith("#"))]


def p_q(s):
    """p and q (kPa) of six stress components (11 22 33 12 13 23)."""
    p = (s[0] + s[1] + s[2]) / 3.0
    d = [s[0] - p, s[1] - p, s[2] - p]
    return p, math.sqrt(1.5 * (d[0] ** 2 + d[1] ** 2 + d[2] ** 2 + 2.0 * (s[3] ** 2 + s[4] ** 2 + s[5] ** 2)))


def turned(f):
    """Fabric turned 90 deg about axis 2 (R e1 = e3, R e3 = -e1): R F R^T."""
    return [f[2], f[1], f[0], -f[5], -f[4], f[3]]


def scene(material, rows, path_file, out_dir, name, variant):
    start = rows[0]
    fabric = [start[k] for k in FABRIC]
    mat = json.loads(json.dumps(material))
    if variant == "turned":
        fabric = turned(fabric)
    if variant == "kf0":
        mat["parameters"]["k_f"] = 0.0
    return {"description": f"replay ({variant}) of the MPM history {name}",
            "material": mat,
            "initial_state": {"stress": [start[k] for k in STRESSES], "void_ratio": start["void_ratio"],
                              "fabric": fabric, "H": start["H"]},
            "steps": [{"preset": "strain_path_csv", "file": path_file, "increments_per_row": 1}],
            "output": {"directory": out_dir, "name": f"{name}_{variant}", "plot": False}}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--run", action="append", required=True, help="LABEL=DIR of an acst_mpm run with particle_*.csv")
    ap.add_argument("--material", required=True, help="the run's material file")
    ap.add_argument("--out", required=True)
    ap.add_argument("--tool", default=os.path.join(ROOT, "build", "driver", "acst_element"))
    a = ap.parse_args()
    with open(a.material) as f:
        material = json.load(f)
    os.makedirs(a.out, exist_ok=True)
    work = os.path.join(a.out, "scenes")
    os.makedirs(work, exist_ok=True)
    cases, scenes = [], []
    for item in a.run:
        label, _, run_dir = item.partition("=")
        if not STEM.match(label):
            sys.exit(f"--run {item!r}: the label must be a plain stem (letters, digits, . _ -)")
        with open(os.path.join(run_dir, "summary.json")) as f:
            s_ult = json.load(f)["S_ult_over_B"]
        files = sorted(glob.glob(os.path.join(run_dir, "particle_*.csv")))
        if not files:
            sys.exit(f"--run {item!r}: no particle_*.csv in {run_dir}")
        for file in files:
            particle = os.path.basename(file)[len("particle_"):-len(".csv")]
            if not STEM.match(particle):
                print(f"skipped {file!r}: not a history name acst_mpm writes", file=sys.stderr)
                continue
            name = f"{label}_{particle}"
            rows = read_rows(file)
            path_file = os.path.join(work, name + "_path.csv")
            with open(path_file, "w", newline="") as f:
                w = csv.writer(f)
                w.writerow(STRAINS)
                for r in rows[1:]:
                    w.writerow([repr(r[k]) for k in STRAINS])
            for v in VARIANTS:
                scene_file = os.path.join(work, f"{name}_{v}.json")
                with open(scene_file, "w") as f:
                    json.dump(scene(material, rows, os.path.abspath(path_file), os.path.abspath(work), name, v), f, indent=1)
                scenes.append(scene_file)
            cases.append((label, particle, name, rows, s_ult))
    done = subprocess.run([a.tool, "--quiet", "--no-plot"] + scenes)
    if done.returncode not in (0, 1):
        return done.returncode
    table = []
    for label, particle, name, rows, s_ult in cases:
        mpm = [p_q([r[k] for k in STRESSES])[1] for r in rows]
        at_peak = min(range(len(rows)), key=lambda i: abs(rows[i]["S_over_B"] - s_ult))
        early = [i for i in range(len(rows)) if rows[i]["S_over_B"] <= EARLY]
        row = {"run": label, "particle": particle, "rows": len(rows), "footing_S_ult_over_B": round(s_ult, 4),
               "rotation_at_peak_deg": round(rows[at_peak]["rotation_deg"], 2),
               "mpm_q_at_peak_kPa": round(mpm[at_peak], 1), "mpm_max_q_kPa": round(max(mpm[i] for i in early), 1)}
        for v in VARIANTS:
            out = os.path.join(work, f"{name}_{v}.csv")
            got = read_rows(out) if os.path.exists(out) else []
            row[f"{v}_complete"] = len(got) == len(rows)
            if not row[f"{v}_complete"]:
                continue
            q = [p_q([g[k] for k in STRESSES])[1] for g in got]
            row[f"{v}_q_at_peak_kPa"] = round(q[at_peak], 1)
            row[f"{v}_max_q_kPa"] = round(max(q[i] for i in early), 1)
            if v == "replay":
                scale = max(abs(p_q([r[k] for k in STRESSES])[0]) for r in rows)
                gaps = [sum((g[k] - r[k]) ** 2 for k in STRESSES) for g, r in zip(got, rows)]
                row["replay_rms_gap_over_max_p"] = round(math.sqrt(sum(gaps) / len(gaps)) / scale, 4)
        table.append(row)
    fields = []
    for r in table:
        fields += [k for k in r if k not in fields]
    with open(os.path.join(a.out, "replays.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(table)
    for r in table:
        print(r)
    plot(a.out, work, cases)
    return 0


def plot(out, work, cases):
    labels = sorted({c[0] for c in cases})
    for label in labels:
        mine = [c for c in cases if c[0] == label]
        cols = 3
        rows_n = (len(mine) + cols - 1) // cols
        script = [f"set terminal pngcairo size {430 * cols},{330 * rows_n} font ',9'",
                  f"set output {gp_quoted(os.path.join(out, label + '_replays.png'))}",
                  f"set multiplot layout {rows_n},{cols} title {gp_quoted(label + ': particles of the footing run, q against S/B: MPM and element-driver replays of their strain paths')}",
                  "set datafile separator ','", "set key top right", "set grid", "set termoption noenhanced",
                  "set xlabel 'S/B'", "set ylabel 'q [kPa]'"]
        for _, particle, name, rows, _ in mine:
            mpm_file = os.path.join(work, f"{name}_mpm.dat")
            with open(mpm_file, "w", newline="") as f:
                csv.writer(f).writerows([r["S_over_B"], p_q([r[k] for k in STRESSES])[1]] for r in rows)
            # The replays' rows follow the history's rows: S/B from the history, q from the replay.
            curves = [f"{gp_quoted(mpm_file)} using 1:2 with lines lw 2 lc rgb 'black' title 'MPM'"]
            for v, colour in zip(VARIANTS, ("#1f77b4", "#d62728", "#2ca02c")):
                merged = os.path.join(work, f"{name}_{v}.dat")
                src = os.path.join(work, f"{name}_{v}.csv")
                if not os.path.exists(src):
                    continue
                got = read_rows(src)
                with open(merged, "w", newline="") as f:
                    csv.writer(f).writerows([r["S_over_B"], p_q([g[k] for k in STRESSES])[1]] for r, g in zip(rows, got))
                title = {"replay": "replay", "turned": "fabric turned 90 deg", "kf0": "k_f = 0"}[v]
                curves.append(f"{gp_quoted(merged)} using 1:2 with lines lc rgb '{colour}' title '{title}'")
            script.append(f"set title {gp_quoted(particle)}")
            script.append("plot " + ", ".join(curves))
        script.append("unset multiplot")
        subprocess.run(["gnuplot"], input="\n".join(script) + "\n", text=True, check=False)


if __name__ == "__main__":
    sys.exit(main())
