#!/usr/bin/env python3
"""Speed against accuracy for the Kimura V85.6 footing (docs/mpm.md, "Quasi-static loading").

Runs the bundled scene with the options that trade accuracy for speed, alone and combined:
  - the symmetric half domain (footing/symmetric_half);
  - a faster footing (footing/speed x f, with and without a speed ramp over 0.01 B) and mass
    scaling (solver/mass_scaling f), f = 2 ... 32, each on the half domain;
  - one stress update per step instead of two halves (solver/stress_update first, last), on the
    half domain;
and compares each with the reference settings (full domain, 0.045 m/s, no mass scaling, same
cell size, same build): change of q_ult (the peak over S/B 0-0.3), RMS difference of the curves over S/B 0-0.3 (sampled
every 0.005 B) over the reference q_ult, the largest kinetic-to-work ratio past S/B 0.02, wall
time. Writes OUT/speedup.csv and OUT/speedup.png (wall time against both errors); runs whose
summary.json or failure record exists are reused, so the study resumes.

  python3 studies/footing_speedup.py [--out DIR] [--threads N] [--only NAME,...] [--tool PATH]
"""
import csv
import json
import math
import os
import subprocess
import sys

from footing_common import (ROOT, gp_quoted, max_kinetic_ratio, read_curve, run_study_case, scene_with_absolute_paths,
                            study_arguments, value_at)

BASE = os.path.join(ROOT, "data", "scenes", "mpm", "kimura_V85.6_alpha0.json")
FACTORS = (2, 4, 8, 16, 32)
CURVES = ("reference", "half_slow2", "half_slow4", "half_speed2", "half_speed4", "half_speed8", "half_mass4",
          "half_mass16", "half_speed8_ramp")  # overlaid in speedup_curves.png


def cases():
    """(name, symmetric half, speed factor, mass scaling, ramp S/B, stress update); the reference
    first. The factor series run on the half domain, which gives the whole's curve (docs/mpm.md)."""
    out = [("reference", False, 1, 1, 0.0), ("half", True, 1, 1, 0.0)]
    out += [(f"half_slow{d}", True, 1 / d, 1, 0.0) for d in (2, 4)]  # is the reference speed quasi-static?
    out += [(f"half_speed{f}", True, f, 1, 0.0) for f in FACTORS]
    out += [(f"half_mass{f}", True, 1, f, 0.0) for f in FACTORS]
    out += [(f"half_speed{f}_ramp", True, f, 1, 0.01) for f in (8, 16, 32)]
    out += [(f"half_speed{f}_mass{m}", True, f, m, 0.0) for f, m in ((4, 4), (8, 2))]
    out = [c + ("average",) for c in out]
    out += [(f"half_stress_{w}", True, 1, 1, 0.0, w) for w in ("first", "last")]
    return out


def scene_for(name, half, speed, mass, ramp, stress_update):
    s = scene_with_absolute_paths(BASE)
    s["name"] = name
    s["output"]["checkpoint_every_s"] = 0
    s["output"]["contours_at_S_over_B"] = []
    s["output"]["contours_at_peak"] = False
    s["output"]["vtk_every_S_over_B"] = 1.0
    s["footing"]["speed"] *= speed
    s["footing"]["symmetric_half"] = half
    s["footing"]["ramp_S_over_B"] = ramp
    s["solver"]["mass_scaling"] = mass
    s["solver"]["stress_update"] = stress_update
    return s


def main():
    a = study_arguments(__doc__, "footing_speedup", "comma-separated case names to run; default: all")
    os.makedirs(a.out, exist_ok=True)
    table = []
    for name, half, speed, mass, ramp, stress_update in cases():
        # a case that failed is not run again: its record up to the failure is what it gives
        run_dir = run_study_case(a, name, lambda: scene_for(name, half, speed, mass, ramp, stress_update),
                                 done=("summary.json", "load_settlement.failed.csv"))
        summary = os.path.join(run_dir, "summary.json")
        failed = os.path.join(run_dir, "load_settlement.failed.csv")
        if os.path.exists(summary):
            with open(summary) as f:
                s = json.load(f)
            record = os.path.join(run_dir, "load_settlement.csv")
        elif os.path.exists(failed):  # the record up to the failure, without a wall time
            s = {"steps": "", "particles": "", "wall_s": float("nan"), "threads": a.threads}
            record = failed
        else:
            continue
        S, q = read_curve(record)
        # The peak over S/B 0-0.3: past the sudden drop at S/B 0.24 the curve depends on rounding
        # and may spike above it (docs/mpm.md, "Symmetric half domain").
        k = max((i for i in range(len(S)) if S[i] <= 0.3), key=lambda i: q[i])
        table.append({"case": name, "symmetric_half": half, "speed_factor": speed, "mass_scaling": mass, "ramp_S_over_B": ramp,
                      "stress_update": stress_update, "q_ult_kPa": q[k], "S_ult_over_B": S[k], "steps": s["steps"],
                      "particles": s["particles"], "wall_s": s["wall_s"], "threads": s["threads"],
                      "max_kinetic_ratio": max_kinetic_ratio(record), "failed_at_S_over_B": S[-1] if record == failed else "",
                      "curve": (S, q)})
    ref = next((r for r in table if r["case"] == "reference"), None)
    if ref is None:
        print("no reference run: nothing to compare", file=sys.stderr)
        return 1
    grid = [0.005 * k for k in range(1, 61)]  # S/B 0.005 ... 0.3
    q_ref = [value_at(*ref["curve"], x) for x in grid]
    for r in table:
        q = [value_at(*r["curve"], x) for x in grid]
        sq = [(a_ - b) ** 2 for a_, b in zip(q, q_ref) if not (math.isnan(a_) or math.isnan(b))]
        r["q_ult_change_pct"] = 100.0 * (r["q_ult_kPa"] / ref["q_ult_kPa"] - 1.0)
        r["curve_rms_pct"] = 100.0 * math.sqrt(sum(sq) / len(sq)) / ref["q_ult_kPa"]
        r["speedup"] = ref["wall_s"] / r["wall_s"]
        print(f"{r['case']:22s} q_ult {r['q_ult_kPa']:7.1f} kPa ({r['q_ult_change_pct']:+6.2f} %)  S_ult/B {r['S_ult_over_B']:.3f}  "
              f"RMS {r['curve_rms_pct']:5.2f} %  K/W {r['max_kinetic_ratio']:.1e}  steps {r['steps']:>6}  "
              f"wall {r['wall_s']:6.1f} s (x{r['speedup']:.1f})" +
              (f"  failed at S/B {r['failed_at_S_over_B']:.3f}" if r["failed_at_S_over_B"] != "" else ""))
    fields = ["case", "symmetric_half", "speed_factor", "mass_scaling", "ramp_S_over_B", "stress_update", "q_ult_kPa", "q_ult_change_pct", "S_ult_over_B",
              "curve_rms_pct", "max_kinetic_ratio", "steps", "particles", "wall_s", "threads", "speedup", "failed_at_S_over_B"]
    with open(os.path.join(a.out, "speedup.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        for r in table:
            w.writerow({k: (round(v, 4) if isinstance(v, float) else v) for k, v in r.items() if k in fields})
    data = os.path.join(a.out, "speedup.dat")
    with open(data, "w") as f:
        for r in table:
            if r["case"] != "reference" and not math.isnan(r["wall_s"]):
                f.write(f"{r['wall_s']} {max(abs(r['q_ult_change_pct']), 0.01)} {max(r['curve_rms_pct'], 0.01)} {r['case']}\n")
    script = "\n".join([
        "set terminal pngcairo size 1000,700 noenhanced",
        f"set output {gp_quoted(os.path.join(a.out, 'speedup.png'))}",
        "set logscale xy", "set grid", "set key top right",
        "set xlabel 'wall time [s], 2 threads'", "set ylabel 'error against the reference settings [%]'",
        f"set title {gp_quoted('Kimura V85.6, cell 0.09 m: speed against accuracy (reference: %.0f s)' % ref['wall_s'])}",
        "set arrow from graph 0,first 2 to graph 1,first 2 nohead dt 2 lc rgb 'gray'",
        "set arrow from 60,graph 0 to 60,graph 1 nohead dt 2 lc rgb 'gray'",
        f"plot {gp_quoted(data)} using 1:2 with points pt 7 ps 1.2 title 'q_ult change', "
        f"{gp_quoted(data)} using 1:3 with points pt 5 ps 1.0 title 'RMS curve difference, S/B 0-0.3', "
        f"{gp_quoted(data)} using 1:3:4 with labels offset 0.8,0.6 left font ',8' notitle", ""])
    subprocess.run(["gnuplot"], input=script, text=True, check=False)
    shown = [r for r in table if r["case"] in CURVES]
    lab = os.path.join(ROOT, "data", "lab", "kimura_1985", "V85.6.csv")
    plots = [f"{gp_quoted(os.path.join(a.out, r['case'], 'load_settlement.csv' if r['failed_at_S_over_B'] == '' else 'load_settlement.failed.csv'))} using 'S_over_B':'q_kPa' with lines "
             f"lw {3 if r['case'] == 'reference' else 1.5} title {gp_quoted(r['case'])}" for r in shown]
    plots.append(f"{gp_quoted(lab)} using 'S_over_B':'q_kPa' with points pt 7 ps 0.5 lc rgb 'black' title 'Kimura et al. (1985) V85.6'")
    script = "\n".join([
        "set terminal pngcairo size 1000,700 noenhanced", "set datafile separator ','", "set datafile commentschars '#'",
        f"set output {gp_quoted(os.path.join(a.out, 'speedup_curves.png'))}", "set key top right", "set grid",
        "set xlabel 'S/B'", "set ylabel 'q = V/B [kPa]'", "set xrange [0:0.3]", "set yrange [0:*]",
        "set title 'Kimura V85.6, cell 0.09 m: load curves of the fast settings against the reference'",
        "plot " + ", ".join(plots), ""])
    subprocess.run(["gnuplot"], input=script, text=True, check=False)
    print(f"wrote {os.path.join(a.out, 'speedup.csv')}, speedup.png and speedup_curves.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
