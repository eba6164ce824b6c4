#!/usr/bin/env python3
"""The graded grid against the uniform one on the Kimura footings (docs/mpm.md, "The graded
grid"; results in bench/results/footing_graded/).

Reads the runs of studies/footing_regularised.py: each graded case (grid=graded, any window,
largest cell and speed) against the uniform case of the same test, cell, internal length and CFL
at the study's speed, its reference. Writes
OUT/graded.csv (case, grid, cell_m, internal_length_m, speed_factor, threads, q_ult_kPa,
S_ult_over_B, rms_vs_reference_pct over the S/B range both runs reach, the same to S/B 0.1 (before
the peak), wall_s, particles, steps, the window and the largest cell) and
OUT/<test>_graded.png (both grids' curves).

  python3 studies/footing_graded.py --uniform DIR --graded DIR [--out DIR]
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess

from footing_common import ROOT, gp_quoted, read_curve

FIELDS = ["case", "grid", "cell_m", "internal_length_m", "speed_factor", "threads", "q_ult_kPa", "S_ult_over_B",
          "rms_vs_reference_pct", "rms_to_SB0.1_pct", "wall_s", "particles", "steps", "window_B", "largest_cell_m", "compared_to_S_over_B",
          "reference", "status"]


def interpolate(S, q, at):
    for i in range(1, len(S)):
        if S[i - 1] <= at <= S[i]:
            return q[i - 1] + (q[i] - q[i - 1]) * (at - S[i - 1]) / (S[i] - S[i - 1])
    return None


def rms_pct(reference, curve, top):
    """RMS of the difference over S/B 0.005 .. top in steps of 0.005, against the reference's RMS."""
    diff = ref = 0.0
    k = 1
    while 0.005 * k <= top + 1e-12:
        a, b = interpolate(*reference, 0.005 * k), interpolate(*curve, 0.005 * k)
        if a is not None and b is not None:
            diff += (b - a) ** 2
            ref += a ** 2
        k += 1
    return 100.0 * math.sqrt(diff / ref) if ref > 0 else float("nan")


def load_record(folder, case):
    """The run's load record: the finished one, or the record of a run that stopped on an error."""
    for name in ("load_settlement.csv", "load_settlement.failed.csv"):
        if os.path.exists(os.path.join(folder, case, name)):
            return read_curve(os.path.join(folder, case, name)), name
    return None, None


def run_row(folder, case, grid, scene_dir):
    with open(os.path.join(scene_dir, case + ".json")) as f:
        scene = json.load(f)
    (S, q), record = load_record(folder, case)
    if os.path.exists(os.path.join(folder, case, "summary.json")):
        with open(os.path.join(folder, case, "summary.json")) as f:
            s = json.load(f)
        s["status"] = "done"
    else:  # stopped on an error: its largest load so far, no wall time
        i = max(range(len(q)), key=lambda k: q[k])
        s = {"threads": scene["solver"].get("threads", ""), "q_ult_kPa": q[i], "S_ult_over_B": S[i], "wall_s": float("nan"),
             "particles": "", "steps": "", "final_S_over_B": S[-1], "status": f"stopped at S/B {S[-1]:.3f} ({record})"}
    reg = scene.get("regularisation")
    l = reg.get("internal_length_m", "default (from the grains at 30 g)") if reg else 0.0
    graded = scene["grid"].get("graded")
    window = graded.get("window_half_width_B", "") if graded is not None else ""
    largest = graded.get("largest_cell", 4 * scene["grid"]["cell_size"]) if graded is not None else ""
    return {"case": case, "grid": grid, "cell_m": scene["grid"]["cell_size"], "internal_length_m": l,
            "window_B": window, "largest_cell_m": largest, "steps": s["steps"],
            "speed_factor": round(scene["footing"]["speed"] / 0.045, 4), "threads": s["threads"],
            "q_ult_kPa": round(s["q_ult_kPa"], 1), "S_ult_over_B": round(s["S_ult_over_B"], 4),
            "wall_s": round(s["wall_s"], 1), "particles": s["particles"], "final": s["final_S_over_B"],
            "status": s["status"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--uniform", required=True, help="footing_regularised.py's folder with the uniform runs")
    ap.add_argument("--graded", required=True, help="its folder with the graded runs")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "footing_graded"))
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    rows, pairs = [], []
    for case in sorted(os.listdir(a.graded)):
        if not case.endswith("_graded") or load_record(a.graded, case)[0] is None:
            continue
        # The uniform run of the same test, cell, length and CFL at the study's speed.
        reference = re.sub(r"_(window|largest)[0-9p]+", "", case[: -len("_graded")])
        reference = re.sub(r"_v[0-9p]+_", "_v1_", reference)
        if not os.path.exists(os.path.join(a.uniform, reference, "summary.json")):
            print(f"{case}: no uniform run {reference} in {a.uniform}")
            continue
        g = run_row(a.graded, case, "graded", os.path.join(a.graded, "scenes"))
        u = run_row(a.uniform, reference, "uniform", os.path.join(a.uniform, "scenes"))
        cu, cg = load_record(a.uniform, reference)[0], load_record(a.graded, case)[0]
        top = round(min(g.pop("final"), u.pop("final")), 3)
        u.update({"rms_vs_reference_pct": 0.0, "rms_to_SB0.1_pct": 0.0, "compared_to_S_over_B": top, "reference": reference})
        g.update({"rms_vs_reference_pct": round(rms_pct(cu, cg, top), 2), "rms_to_SB0.1_pct": round(rms_pct(cu, cg, 0.1), 2),
                  "compared_to_S_over_B": top, "reference": reference})
        if not any(r["case"] == reference for r in rows):
            rows.append(u)
        rows.append(g)
        pairs.append((case, cu, cg, f"{case.split('_')[0].replace('p', '.')}, h = {g['cell_m']:g} m, window {g['window_B']:g} B, "
                      f"{g['speed_factor']:g} x speed: graded grid against the uniform one"))
        print(json.dumps(g))
    with open(os.path.join(a.out, "graded.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        w.writerows(rows)
    for case, cu, cg, title in pairs:
        lines = ["set terminal pngcairo size 900,600 noenhanced", f"set output {gp_quoted(os.path.join(a.out, case + '.png'))}",
                 "set grid", "set key top right", "set xlabel 'S/B'", "set ylabel 'q [kPa]'", "set xrange [0:0.25]",
                 "set yrange [0:2000]", f"set title {gp_quoted(title)}",
                 "plot '-' using 1:2 with lines lw 2 title 'uniform grid', '-' using 1:2 with lines lw 2 dt 2 title 'graded grid'"]
        for S, q in (cu, cg):
            step = max(1, len(S) // 2000)
            lines.append("\n".join(f"{x} {y}" for x, y in zip(S[::step], q[::step])) + "\ne")
        subprocess.run(["gnuplot"], input="\n".join(lines), text=True, check=False)


if __name__ == "__main__":
    main()
