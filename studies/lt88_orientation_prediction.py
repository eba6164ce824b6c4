#!/usr/bin/env python3
"""Held-out prediction: peak friction angle against the bedding angle in triaxial and plane-strain
compression (Lam & Tatsuoka 1988, Fig. 21(a); data/lab/lam_tatsuoka_1988/phi_vs_orientation.csv).

No fit uses these rows (the delivered description fits the Fig. 9 plane-strain curves at bedding 0
and the friction angles against b; data/calibration/README.md). Each row with the deposition
direction in the sigma1-sigma3 plane (xi = 90 deg: TC-3 and PSC-3, bedding angle omega 0-90 deg)
is run with acst_element: e_0.3 = 0.70 at 29.4 kPa, consolidated isotropically to 98 kPa, then
drained triaxial or plane-strain compression to 12 % axial strain in steps of 0.02 %; the peak of
asin((sigma1 - sigma3)/(sigma1 + sigma3)) is compared with the measured angle. Every parameter
set named is run. Writes OUT/orientation_prediction.csv (one row per set and test) and
OUT/orientation_prediction.png (angles against omega, measured and predicted).

  python3 studies/lt88_orientation_prediction.py [--out DIR] [--tool PATH] [--sets STEM,...]
"""
import csv
import json
import math
import os
import subprocess
import tempfile

from footing_common import ROOT, gp_quoted, tool_arguments, write_table

DATA = os.path.join(ROOT, "data", "lab", "lam_tatsuoka_1988", "phi_vs_orientation.csv")
SERIES = {"TC-3 (H/W=1.0)": "drained_triaxial_compression", "PSC-3 (H/W=1.9)": "plane_strain_compression"}
SIGMA3, E03, P03 = 98.0, 0.70, 29.4  # kPa, e_0.3 and the stress it was measured at (file header)
SETS = "toyoura_acst_calibrated,toyoura_acst_li2002_calibrated,toyoura_isotropic_calibrated"


def measured_rows():
    with open(DATA) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return [r for r in rows if r["series"] in SERIES and float(r["xi_deg"]) == 90.0]


def peak_angle(tool, set_stem, preset, omega, work):
    name = f"{set_stem}_{preset}_{int(omega)}"
    scene = {"description": f"Lam & Tatsuoka (1988) Fig. 21(a) row: {preset}, bedding {omega} deg",
             "material": {"file": os.path.join(ROOT, "data", "parameters", set_stem + ".json")},
             "initial_state": {"confining_pressure": P03, "void_ratio": E03, "bedding_angle_deg": omega},
             "steps": [{"preset": "isotropic_compression", "p_to": SIGMA3, "increments": 20},
                       {"preset": preset, "axial_strain_pct": 12.0, "increments": 600}]}
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(scene, f)
    subprocess.run([tool, "--quiet", "--no-plot", "--output", work, path], check=True)
    with open(os.path.join(work, name + ".csv")) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    best = 0.0
    for r in rows:
        s = sorted((float(r["sigma_11_kPa"]), float(r["sigma_22_kPa"]), float(r["sigma_33_kPa"])))
        best = max(best, math.degrees(math.asin((s[2] - s[0]) / (s[2] + s[0]))))
    return best


def main():
    a = tool_arguments(__doc__, "lt88_orientation_prediction", "driver/acst_element",
                       [("--sets", {"default": SETS, "help": "comma-separated parameter-set stems in data/parameters"})])
    os.makedirs(a.out, exist_ok=True)
    sets = a.sets.split(",")
    table = []
    with tempfile.TemporaryDirectory() as work:
        for r in measured_rows():
            omega, phi = float(r["omega_deg"]), float(r["phi_deg"])
            row = {"test": SERIES[r["series"]], "omega_deg": omega, "measured_phi_deg": phi}
            for s in sets:
                row[s] = round(peak_angle(a.tool, s, SERIES[r["series"]], omega, work), 3)
            table.append(row)
            print(row, flush=True)
    out_csv = os.path.join(a.out, "orientation_prediction.csv")
    write_table(out_csv, list(table[0]), table)
    for s in sets:
        for test in SERIES.values():
            d = [t[s] - t["measured_phi_deg"] for t in table if t["test"] == test]
            print(f"{s} {test}: mean {sum(d) / len(d):+.2f} deg, RMS {math.sqrt(sum(x * x for x in d) / len(d)):.2f} deg")
    lines = ["set terminal pngcairo noenhanced size 1200,550", "set output " + gp_quoted(os.path.join(a.out, "orientation_prediction.png")),
             "set datafile separator ','", "set key below", "set xrange [-5:95]", "set xtics 30", "set grid",
             "set xlabel 'bedding angle omega (deg)'",
             "set ylabel 'peak friction angle (deg)'", "set multiplot layout 1,2"]
    for i, test in enumerate(SERIES.values()):
        cond = f"(strcol(1) eq {gp_quoted(test)} ? $%d : 1/0)"
        plots = [f"{gp_quoted(out_csv)} using 2:{cond % 3} with points pt 7 ps 1.5 title 'measured'"]
        plots += [f"{gp_quoted(out_csv)} using 2:{cond % (4 + k)} with linespoints title {gp_quoted(s)}" for k, s in enumerate(sets)]
        lines += [f"set title {gp_quoted(test)}", "plot " + ", ".join(plots)]
    subprocess.run(["gnuplot"], input="\n".join(lines), text=True, check=False)


if __name__ == "__main__":
    main()
