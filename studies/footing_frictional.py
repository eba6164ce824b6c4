#!/usr/bin/env python3
"""The MPM's own error on a frictional, dilating soil with a closed form (docs/footing-study.md,
"The discretisation's own error on a frictional soil"; results in bench/results/footing_frictional/).

The Kimura footing's geometry, grids and solver (the half-domain convergence scene of V85.6,
data/scenes/mpm/convergence/, rough footing B = 0.9 m at 0.045 m/s), with the sand replaced by
weightless, perfectly plastic Drucker-Prager soil matched to Mohr-Coulomb in plane strain
(friction angle phi, dilation angle psi, cohesion c; no surcharge). Under associated flow
(psi = phi) its limit load is Prandtl's q = c N_c, N_c = (exp(pi tan phi) tan^2(45 + phi/2) - 1)
cot phi, for a rough or a smooth base alike. So the gap between the run's load and c N_c is the
method's (grid, contact, particle update, loading speed) on a soil that, like the dense sand,
gains strength with pressure and dilates as it shears, at the cells the sand runs use.

q = V/B averaged over S/B 0.03-0.06 (past collapse, which E = 10^4 c reaches by S/B 0.02).
Writes OUT/frictional.csv (case, grid, cell_m, friction_angle_deg, dilation_angle_deg,
cohesion_kPa, q_closed_form_kPa, q_mean_kPa, error_pct, q_at_SB0.02_kPa, wall_s) and
OUT/q_against_h.png. A case whose summary.json exists is not run again.

  python3 studies/footing_frictional.py [--out DIR] [--threads 2] [--stop 0.06] CASE ...
  CASE: h=0.045[,grid=uniform|graded][,phi=30][,psi=phi][,c=10][,E=1e5][,above=6]
        (above: the grid's cells above the soil, for the heave; the scene's 6 unless given)
"""
import json
import math
import os
import subprocess
import sys

from footing_common import ROOT, footing_cases_arguments, gp_quoted, old_rows, run_and_read, scene_with_absolute_paths, write_table

BASE = os.path.join(ROOT, "data", "scenes", "mpm", "convergence", "kimura_V85.6_alpha0_h0045.json")
FIELDS = ["case", "grid", "cell_m", "friction_angle_deg", "dilation_angle_deg", "cohesion_kPa", "E_kPa",
          "q_closed_form_kPa", "q_mean_kPa", "error_pct", "q_at_SB0.02_kPa", "wall_s", "status"]
WINDOW = (0.03, 0.06)


def prandtl_nc(phi_deg):
    t = math.tan(math.radians(phi_deg))
    if t == 0.0:
        return 2.0 + math.pi
    nq = math.exp(math.pi * t) * math.tan(math.radians(45.0 + phi_deg / 2.0)) ** 2
    return (nq - 1.0) / t


def parse_case(text):
    c = {"h": None, "grid": "uniform", "phi": 30.0, "c": 10.0, "E": 1e5}
    for p in text.split(","):
        k, v = p.split("=", 1)
        if k not in ("h", "grid", "phi", "psi", "c", "E", "above"):
            sys.exit(f"{text}: unknown key {k} (h, grid, phi, psi, c, E, above)")
        c[k] = v if k == "grid" else float(v)
    if c["h"] is None or c["grid"] not in ("uniform", "graded"):
        sys.exit(f"{text}: h is required and grid is uniform or graded")
    c.setdefault("psi", c["phi"])
    c["name"] = (f"dp_phi{c['phi']:g}_psi{c['psi']:g}_c{c['c']:g}_E{c['E']:g}_h{c['h']:g}_{c['grid']}").replace(".", "p")
    return c


def scene_of(c, stop, threads):
    s = scene_with_absolute_paths(BASE)
    s["name"] = c["name"]
    s["description"] = ("Weightless Drucker-Prager soil under the Kimura footing's geometry (footing_frictional.py): "
                        f"phi {c['phi']:g}, psi {c['psi']:g}, c {c['c']:g} kPa")
    s["grid"]["cell_size"] = c["h"]
    if "above" in c:
        s["grid"]["cells_above"] = int(c["above"])
    if c["grid"] == "graded":
        s["grid"]["graded"] = {}  # the documented window (3 B), growth and largest cell
    s["materials"] = {"soil": {"model": "drucker_prager", "parameters": {
        "E": c["E"], "nu": 0.3, "friction_angle_deg": c["phi"], "cohesion": c["c"], "dilation_angle_deg": c["psi"]}}}
    body = s["bodies"][0]
    s["bodies"] = [{k: body[k] for k in ("name", "x_range", "y_range", "density", "particles_per_cell")}]
    s["bodies"][0]["material"] = "soil"
    for key in ("gravity", "initial_stress", "surcharge_kPa"):
        s.pop(key, None)
    s["solver"]["threads"] = threads
    s["stop"] = {"S_over_B": stop}
    s["output"] = {"checkpoint_every_s": 600}
    return s


def mean_between(S, q, lo, hi):
    v = [y for x, y in zip(S, q) if lo <= x <= hi]
    return sum(v) / len(v) if v else float("nan")


def main():
    a = footing_cases_arguments(__doc__, os.path.join(ROOT, "bench", "results", "footing_frictional"), 0.06)
    rows = []
    for text in a.cases:
        c = parse_case(text)
        got = run_and_read(a.tool, a.out, c["name"], scene_of(c, a.stop, a.threads), c["h"], rows)
        if got is None:
            continue
        _, summary, (S, q) = got
        closed = c["c"] * prandtl_nc(c["phi"]) if c["psi"] == c["phi"] else None  # Prandtl's needs associated flow
        mean = mean_between(S, q, *WINDOW)
        rows.append({"case": c["name"], "grid": c["grid"], "cell_m": c["h"], "friction_angle_deg": c["phi"],
                     "dilation_angle_deg": c["psi"], "cohesion_kPa": c["c"], "E_kPa": c["E"],
                     "q_closed_form_kPa": round(closed, 1) if closed else "", "q_mean_kPa": round(mean, 1),
                     "error_pct": round(100.0 * (mean / closed - 1.0), 2) if closed else "", "q_at_SB0.02_kPa": round(mean_between(S, q, 0.0195, 0.0205), 1),
                     "wall_s": round(summary["wall_s"], 1), "status": "done", "curve": (S, q)})
        print(json.dumps({k: v for k, v in rows[-1].items() if k != "curve"}), flush=True)
    table = os.path.join(a.out, "frictional.csv")
    write_table(table, FIELDS, old_rows(table, rows) + rows)
    plot(a.out, rows)


def plot(out, rows):
    done = [r for r in rows if r.get("status") == "done"]
    if not done:
        return
    # The method's error against the cell, for each friction angle's graded, associated runs.
    series = []
    for phi in sorted({r["friction_angle_deg"] for r in done}):
        pts = sorted((r["cell_m"], r["error_pct"]) for r in done if r["friction_angle_deg"] == phi
                     and r["grid"] == "graded" and r["error_pct"] != "")
        if pts:
            series.append((f"associated, phi = {phi:g} deg, graded grid", "\n".join(f"{h},{e}" for h, e in pts) + "\ne"))
    lines = ["set terminal pngcairo size 1600,560 noenhanced", "set datafile separator ','",
             f"set output {gp_quoted(os.path.join(out, 'q_against_h.png'))}",
             f"set multiplot layout 1,{2 if series else 1}", "set grid",
             "set key outside right font ',9'", "set xlabel 'S/B'", "set ylabel 'q = V/B [kPa]'", "set xrange [0:*]",
             "set title 'Weightless Drucker-Prager soil under the Kimura footing (B = 0.9 m)'"]
    plots = [f"{gp_quoted(os.path.join(out, r['case'], 'load_settlement.csv'))} using 'S_over_B':'q_kPa' with lines lw 2 "
             f"title {gp_quoted(r['grid'] + ' h = ' + str(r['cell_m']) + ' m, phi ' + str(r['friction_angle_deg']) + ', psi ' + str(r['dilation_angle_deg']))}"
             for r in done]
    closed = sorted({r["q_closed_form_kPa"] for r in done if r["q_closed_form_kPa"] != ""})
    plots += [f"{v} with lines dt 2 lc rgb 'black' title {gp_quoted('c N_c = ' + str(v) + ' kPa')}" for v in closed]
    lines.append("plot " + ", ".join(plots))
    if series:
        lines += ["set xlabel 'cell size h [m]'", "set ylabel 'q over S/B 0.03-0.06 against c N_c [%]'", "set xrange [0:0.1]",
                  "set yrange [0:*]", "set key top left", "set title 'The method''s error against Prandtl'",
                  "plot " + ", ".join(f"'-' using 1:2 with linespoints pt 7 lw 2 title {gp_quoted(t)}" for t, _ in series)]
        lines += [d for _, d in series]
    lines += ["unset multiplot", ""]
    subprocess.run(["gnuplot"], input="\n".join(lines), text=True, check=False)


if __name__ == "__main__":
    main()
