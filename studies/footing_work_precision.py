#!/usr/bin/env python3
"""Work-precision of the converged footing (issue 78 item 3): the cost of each case of the sweep
data/sweeps/work_precision.json (wall time on its threads, and particle-steps, which do not depend
on the machine) against its error relative to the reference case (the finest cell): the first
peak's and the largest load's relative error, and the curve's RMS difference over S/B
0.005-0.2 in % of the reference's largest load. The default case is marked.

  mpirun -n 2 build/mpm_adapter/acst_sweep --threads 1 --budget MIN \\
      --output data/sweeps/recorded/work_precision data/sweeps/work_precision.json
  python3 studies/footing_work_precision.py [--sweep data/sweeps/recorded/work_precision] \\
      [--reference cell_0.0225] [--out bench/results/footing_work_precision]

Reads the sweep folder's table.json and each case's kept load record (kept/CASE/); writes
OUT/work_precision.csv and OUT/work_precision.png (gnuplot). Cases not done are listed and left out.
"""
import argparse
import json
import os
import subprocess
import sys

from footing_common import ROOT, gp_quoted, read_curve, rms_difference_pct, write_table

FIELDS = ("case", "group", "cell_m", "particles", "steps", "particle_steps", "threads", "wall_s",
          "q_first_peak_kPa", "q_ult_kPa", "first_peak_error_pct", "largest_load_error_pct", "curve_rms_pct")


def relative_error_pct(value, reference):
    if value in (None, "") or reference in (None, ""):
        return ""
    return round(100.0 * (float(value) - float(reference)) / float(reference), 2)


def rows_of(sweep, reference_name, upto):
    if not os.path.isfile(os.path.join(sweep, "table.json")):
        sys.exit(f"no table.json in {sweep}: run the sweep into it first (the command in this script's help)")
    with open(os.path.join(sweep, "table.json")) as f:
        cases = json.load(f)["cases"]
    done = {c["case"]: c for c in cases if c.get("status") == "done"}
    waiting = [c["case"] for c in cases if c.get("status") != "done"]
    if reference_name not in done:
        sys.exit(f"the reference case {reference_name} is not done in {sweep} (waiting: {', '.join(waiting) or 'none'})")
    curves = {name: read_curve(os.path.join(sweep, "kept", name, "load_settlement.csv")) for name in done}
    ref = done[reference_name]
    q_scale = max(curves[reference_name][1])
    rows = []
    for name, c in done.items():
        rows.append({
            "case": name, "group": c["group"], "cell_m": c["cell_m"], "particles": c["particles"],
            "steps": c["steps"], "particle_steps": int(c["particles"]) * int(c["steps"]), "threads": c["threads"],
            "wall_s": c["wall_s"], "q_first_peak_kPa": c["q_first_peak_kPa"], "q_ult_kPa": c["q_ult_kPa"],
            "first_peak_error_pct": relative_error_pct(c["q_first_peak_kPa"], ref["q_first_peak_kPa"]),
            "largest_load_error_pct": relative_error_pct(c["q_ult_kPa"], ref["q_ult_kPa"]),
            "curve_rms_pct": "" if name == reference_name else rms_difference_pct(curves[name], curves[reference_name], upto, q_scale),
        })
    return rows, waiting


def plot(out, rows, reference_name):
    """Two panels, wall time and particle-steps on x, |error| on y (log-log), one point type per
    measure, each point labelled with its case; the default ringed."""
    data = os.path.join(out, "work_precision.dat")
    with open(data, "w") as f:
        for r in rows:
            if r["case"] == reference_name:
                continue
            errors = [abs(r[k]) if r[k] != "" else float("nan") for k in
                      ("first_peak_error_pct", "largest_load_error_pct", "curve_rms_pct")]
            errors = [max(e, 0.01) for e in errors]  # an error of 0 drawn on the log scale's floor
            f.write(f"{r['wall_s']} {r['particle_steps']} {errors[0]} {errors[1]} {errors[2]} "
                    f"{'1' if r['case'] == 'default' else '0'} {r['case']}\n")
    png = os.path.join(out, "work_precision.png")
    d = gp_quoted(data)
    panels = []
    for col, label in ((1, "wall time on the case's threads [s]"), (2, "particle-steps")):
        panels.append(f"""
set xlabel {gp_quoted(label)}
plot {d} u {col}:3 w p pt 7 ps 1.2 lc rgb '#1f77b4' t 'first peak', \\
     {d} u {col}:4 w p pt 5 ps 1.2 lc rgb '#d62728' t 'largest load', \\
     {d} u {col}:5 w p pt 9 ps 1.4 lc rgb '#2ca02c' t 'curve RMS to S/B 0.2', \\
     {d} u {col}:($6 > 0 ? $5 : 1/0) w p pt 6 ps 3 lw 2 lc rgb 'black' t 'default', \\
     {d} u {col}:5:7 w labels offset 0,1 font ',8' notitle""")
    script = f"""set terminal pngcairo noenhanced size 1500,620 font ',11'
set output {gp_quoted(png)}
set multiplot layout 1,2 title {gp_quoted('Converged footing V85.6 to S/B 0.2: cost against the error relative to ' + reference_name)}
set logscale xy
set grid
set ylabel '|error| [%]'
set key top right
{''.join(panels)}
unset multiplot
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    return png


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sweep", default=os.path.join(ROOT, "data", "sweeps", "recorded", "work_precision"))
    ap.add_argument("--reference", default="cell_0.0225")
    ap.add_argument("--upto", type=float, default=0.2, help="the curve's RMS over S/B 0.005 to this")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "footing_work_precision"))
    a = ap.parse_args()
    rows, waiting = rows_of(a.sweep, a.reference, a.upto)
    os.makedirs(a.out, exist_ok=True)
    write_table(os.path.join(a.out, "work_precision.csv"), FIELDS, rows)
    png = plot(a.out, rows, a.reference)
    print(f"{len(rows)} cases; waiting: {', '.join(waiting) or 'none'}; {png}")


if __name__ == "__main__":
    main()
