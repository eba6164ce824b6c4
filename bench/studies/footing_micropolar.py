#!/usr/bin/env python3
"""The Kimura footings with micropolar rotations (docs/mpm.md, "Micropolar rotations";
docs/footing-study.md, "Micropolar rotations"; results in bench/results/footing_micropolar/).

Each case is footing_regularised.py's (the half-domain convergence scene of its test on the
graded grid, the delivered set, the local sand: no averaged void ratio) with the core's
micropolar rotations of length lc (default: Toyoura's grain diameter at Kimura's 30 g, 0.0051 m).
The runs go to RUNS/<case>/ (a case with a summary.json is not run again); OUT gets
convergence.csv (the issue's columns, the micropolar length and the first peak), each run's load
record thinned to 400 rows, q_ult_against_h.png (the first peak and the largest load against the
cell, beside the averaged void ratio's and the local model's graded runs from
bench/results/footing_regularised/convergence.csv) and <test>_curves.png.

  python3 bench/studies/footing_micropolar.py --runs RUNS [--out DIR] [--threads 2] [--stop 0.2] CASE ...
  CASE: TEST,h=0.03[,lc=0.0051][,kc=0.5][,speed=1][,cfl=0.5]   (TEST V85.6 or H86.7)
"""
import csv
import json
import os
import subprocess

import footing_regularised as fr
from footing_common import (ROOT, footing_cases_arguments, gp_quoted, old_rows, plot_beside_kimura, run_and_read, value_at,
                            write_table)

DEFAULT_LENGTH = 0.17e-3 * 30  # Toyoura's d50 at 30 g (internal_length.hpp, micropolar_length_from_grains)
FIELDS = ["case", "cell_m", "internal_length_m", "micropolar_length_m", "speed_factor", "cfl", "q_ult_kPa",
          "S_ult_over_B", "wall_s", "q_first_peak_kPa", "S_first_peak_over_B", "q_at_SB0.1_kPa", "final_S_over_B",
          "max_kinetic_ratio", "status"]
NONLOCAL = os.path.join(ROOT, "bench", "results", "footing_regularised", "convergence.csv")


def case_of(text):
    parts = text.split(",")
    extra = {k: v for k, v in (p.split("=", 1) for p in parts[1:])}
    extra.setdefault("lc", str(DEFAULT_LENGTH))
    return fr.parse_case(",".join([parts[0], "grid=graded", "l=0"] + [f"{k}={v}" for k, v in extra.items()]))


def thinned(S, q, rows=400):
    step = max(1, len(S) // rows)
    keep = sorted(set(range(0, len(S), step)) | {len(S) - 1, max(range(len(q)), key=lambda i: q[i])})
    return [(S[i], q[i]) for i in keep]


def main():
    a = footing_cases_arguments(__doc__, os.path.join(ROOT, "bench", "results", "footing_micropolar"), 0.2,
                                [("--runs", {"required": True, "help": "folder of the runs (large: VTK frames)"})])
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for text in a.cases:
        c = case_of(text)
        got = run_and_read(a.tool, a.runs, c["name"], fr.scene_of(c, a.stop, a.threads), c["h"], rows)
        if got is None:
            continue
        _, s, (S, q) = got
        with open(os.path.join(a.out, c["name"] + "_load.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["S_over_B", "q_kPa"])
            w.writerows((f"{x:.5f}", f"{y:.2f}") for x, y in thinned(S, q))
        r = {"case": c["name"], "test": c["test"], "cell_m": c["h"], "internal_length_m": 0.0, "micropolar_length_m": c["lc"],
             "speed_factor": c["speed"], "cfl": c["cfl"], "q_ult_kPa": round(s["q_ult_kPa"], 1),
             "S_ult_over_B": round(s["S_ult_over_B"], 4), "wall_s": round(s["wall_s"], 1),
             "q_first_peak_kPa": s["q_first_peak_kPa"] and round(s["q_first_peak_kPa"], 1),
             "S_first_peak_over_B": s["S_first_peak_over_B"] and round(s["S_first_peak_over_B"], 4),
             "q_at_SB0.1_kPa": round(value_at(S, q, 0.1), 1), "final_S_over_B": round(s["final_S_over_B"], 4),
             "max_kinetic_ratio": s["max_kinetic_ratio"], "status": "done"}
        rows.append(r)
        print(json.dumps(r), flush=True)
    table = os.path.join(a.out, "convergence.csv")
    every = old_rows(table, rows) + rows
    write_table(table, FIELDS, every)
    figures(a.out, [r for r in every if r.get("status") == "done"])


def figures(out, rows):
    with open(NONLOCAL) as f:
        others = [r for r in csv.DictReader(f) if r["status"].startswith(("done", "stopped")) and r.get("grid") == "graded"
                  and r.get("set") == "acst" and float(r["speed_factor"]) == 1.0 and float(r["cfl"]) == 0.5]
    lines = ["set terminal pngcairo size 1300,520 noenhanced", f"set output {gp_quoted(os.path.join(out, 'q_ult_against_h.png'))}",
             "set multiplot layout 1,2", "set grid", "set key bottom left", "set xlabel 'finest cell h [m]'",
             "set ylabel 'q [kPa]'", "set xrange [0:0.05]", "set yrange [0:2200]"]
    data = lambda pts: "\n".join(f"{x} {y}" for x, y in sorted(pts)) + "\ne"
    for test in ("V85.6", "H86.7"):
        tag = test.replace(".", "p")
        mine = [r for r in rows if r["case"].startswith(tag) and abs(float(r["micropolar_length_m"]) - DEFAULT_LENGTH) < 1e-9
                and float(r["speed_factor"]) == 1.0 and float(r["cfl"]) == 0.5]
        averaged = [r for r in others if r["case"].startswith(tag) and r["internal_length_m"] == "default"
                    and "_m" not in r["case"].split("_cfl")[1]
                    and ("window" not in r["case"] or "window3" in r["case"])]
        local = [r for r in others if r["case"].startswith(tag) and r["internal_length_m"] in ("0", "0.0")]
        series = [(f"micropolar, lc = {DEFAULT_LENGTH:g} m: first peak", mine, "q_first_peak_kPa", "lw 2 pt 7 lc rgb '#9400d3'"),
                  ("micropolar: largest load", mine, "q_ult_kPa", "lw 2 pt 6 dt 2 lc rgb '#9400d3'"),
                  ("averaged void ratio, l = 0.085 m: first peak", averaged, "q_first_peak_kPa", "lw 2 pt 5 lc rgb '#009e73'"),
                  ("averaged void ratio: largest load", averaged, "q_ult_kPa", "lw 2 pt 4 dt 2 lc rgb '#009e73'"),
                  ("local: first peak", local, "q_first_peak_kPa", "lw 2 pt 9 lc rgb '#e69f00'")]
        series = [(t, [(float(r["cell_m"]), float(r[k])) for r in rs if r.get(k)], style) for t, rs, k, style in series]
        series = [x for x in series if x[1]]
        if not series:
            continue
        lines += [f"set title {gp_quoted(test + ': the load against the finest cell (graded grid, to S/B 0.2-0.25)')}",
                  "plot " + ", ".join(f"'-' using 1:2 with linespoints {style} title {gp_quoted(t)}" for t, _, style in series)]
        lines += [data(pts) for _, pts, _ in series]
    lines += ["unset multiplot", ""]
    subprocess.run(["gnuplot"], input="\n".join(lines), text=True, check=False)
    panels = {}
    for test in ("V85.6", "H86.7"):
        mine = sorted((float(r["cell_m"]), float(r["micropolar_length_m"]), r["case"]) for r in rows
                      if r["case"].startswith(test.replace(".", "p")))
        if mine:
            panels[test] = (f"{test}: micropolar rotations against the centrifuge",
                            [(os.path.join(out, case + "_load.csv"), f"h = {h:g} m, lc = {lc:g} m") for h, lc, case in mine])
    for test, panel in panels.items():
        plot_beside_kimura(os.path.join(out, test + "_curves.png"), {test: panel}, 0.2, key="bottom right")


if __name__ == "__main__":
    main()
