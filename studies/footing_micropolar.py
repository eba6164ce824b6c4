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

  python3 studies/footing_micropolar.py --runs RUNS [--out DIR] [--threads 2] [--stop 0.2] CASE ...
  CASE: TEST,h=0.03[,lc=0.0051][,kc=0.5][,speed=1][,cfl=0.5]   (TEST one of the reference study's kimura group,
        V85.6, V75.1, V64.6, H86.7, H76.5, H61.0)

With runs of all six tests at one cell, kimura_six.png draws their first peaks and largest loads
against the relative density (V and H series, the centrifuge's where data/lab/kimura_1985/ has
them) and kimura_six_curves.png the V and H curves of each density pair.
"""
import csv
import json
import os
import subprocess

import footing_regularised as fr
from footing_common import (ROOT, footing_cases_arguments, gp_quoted, old_rows, plot_beside_kimura, read_curve, run_and_read,
                            value_at, write_table)

DEFAULT_LENGTH = 0.17e-3 * 30  # Toyoura's d50 at 30 g (internal_length.hpp, micropolar_length_from_grains)
FIELDS = ["case", "cell_m", "internal_length_m", "micropolar_length_m", "speed_factor", "cfl", "q_ult_kPa",
          "S_ult_over_B", "wall_s", "q_first_peak_kPa", "S_first_peak_over_B", "q_at_SB0.1_kPa", "q_mean_SB0.08_0.2_kPa",
          "final_S_over_B", "max_kinetic_ratio", "status"]
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


def mean_between(points, a, b):
    """The load's mean over S/B from a to b (trapezoids over the points in [a, b]): past the first
    peak the curve steps between branches, and its mean is the steadier measure of what it carries."""
    pts = [(x, y) for x, y in points if a <= x <= b]
    if len(pts) < 2 or pts[-1][0] - pts[0][0] < 0.9 * (b - a):
        return None
    area = sum((x1 - x0) * (y0 + y1) / 2 for (x0, y0), (x1, y1) in zip(pts, pts[1:]))
    return round(area / (pts[-1][0] - pts[0][0]), 1)


MEAN_FROM, MEAN_TO = 0.08, 0.2


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
        kept = [(float(f"{x:.5f}"), float(f"{y:.2f}")) for x, y in thinned(S, q)]
        with open(os.path.join(a.out, c["name"] + "_load.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["S_over_B", "q_kPa"])
            w.writerows((f"{x:.5f}", f"{y:.2f}") for x, y in kept)
        r = {"case": c["name"], "test": c["test"], "cell_m": c["h"], "internal_length_m": 0.0, "micropolar_length_m": c["lc"],
             "speed_factor": c["speed"], "cfl": c["cfl"], "q_ult_kPa": round(s["q_ult_kPa"], 1),
             "S_ult_over_B": round(s["S_ult_over_B"], 4), "wall_s": round(s["wall_s"], 1),
             "q_first_peak_kPa": s["q_first_peak_kPa"] and round(s["q_first_peak_kPa"], 1),
             "S_first_peak_over_B": s["S_first_peak_over_B"] and round(s["S_first_peak_over_B"], 4),
             "q_at_SB0.1_kPa": round(value_at(S, q, 0.1), 1), "q_mean_SB0.08_0.2_kPa": mean_between(kept, MEAN_FROM, MEAN_TO),
             "final_S_over_B": round(s["final_S_over_B"], 4),
             "max_kinetic_ratio": s["max_kinetic_ratio"], "status": "done"}
        rows.append(r)
        print(json.dumps(r), flush=True)
    table = os.path.join(a.out, "convergence.csv")
    every = old_rows(table, rows) + rows
    for r in every:  # rows recorded before the mean was a column: from their kept load records
        record = os.path.join(a.out, r["case"] + "_load.csv")
        if not r.get("q_mean_SB0.08_0.2_kPa") and os.path.isfile(record):
            r["q_mean_SB0.08_0.2_kPa"] = mean_between(list(zip(*read_curve(record))), MEAN_FROM, MEAN_TO)
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
    label = lambda h, lc, v, cfl: f"h = {h:g} m, lc = {lc:g} m" + (f", speed x {v:g}" if v != 1 else "") + (
        f", CFL {cfl:g}" if cfl != 0.5 else "")
    for test in ("V85.6", "H86.7"):
        mine = sorted((float(r["cell_m"]), float(r["micropolar_length_m"]), float(r["speed_factor"]), float(r["cfl"]), r["case"])
                      for r in rows if r["case"].startswith(test.replace(".", "p")))
        # The cells and lengths at the study's speed and CFL; then the speeds and time steps at each cell that has them.
        study = [m for m in mine if m[2] == 1 and m[3] == 0.5]
        varied = {m[0] for m in mine if (m[2], m[3]) != (1, 0.5)}
        for png, runs, title in ((test + "_curves.png", study, "micropolar rotations against the centrifuge"),
                                 (test + "_speed_curves.png", [m for m in mine if m[0] in varied and abs(m[1] - DEFAULT_LENGTH) < 1e-9],
                                  "the loading speed and the time step")):
            if runs:
                plot_beside_kimura(os.path.join(out, png), {test: (f"{test}: {title}", [
                    (os.path.join(out, case + "_load.csv"), label(h, lc, v, cfl)) for h, lc, v, cfl, case in runs])}, 0.2,
                    key="bottom right")
    six_figures(out, rows)


def test_of(case):
    return case.split("_h")[0].replace("p", ".")


def measured_peaks():
    """{test: (D_r, q_peak)} of the centrifuge tests data/lab/kimura_1985/ holds."""
    with open(os.path.join(ROOT, "data", "lab", "kimura_1985", "tests_meta.csv")) as f:
        return {r["test_id"]: (float(r["D_r_pct"]), float(r["q_peak_kPa"]))
                for r in csv.DictReader(line for line in f if not line.startswith("#"))}


def six_figures(out, rows):
    """The six Kimura tests at the coarsest cell that holds all six (default lc, study's speed and CFL);
    a test whose load rises to the end has no first peak."""
    default = [r for r in rows if abs(float(r["micropolar_length_m"]) - DEFAULT_LENGTH) < 1e-9
               and float(r["speed_factor"]) == 1.0 and float(r["cfl"]) == 0.5]
    cells = sorted({float(r["cell_m"]) for r in default if len({test_of(x["case"]) for x in default
                                                                 if float(x["cell_m"]) == float(r["cell_m"])}) == 6})
    if not cells:
        return
    h = cells[-1]
    runs = {test_of(r["case"]): r for r in default if float(r["cell_m"]) == h}
    density = {t: b["relative_density_pct"] for t, b in fr.KIMURA_TESTS.items()}
    measured = measured_peaks()
    lines = ["set terminal pngcairo size 900,600 noenhanced", f"set output {gp_quoted(os.path.join(out, 'kimura_six.png'))}",
             "set grid", "set key top left", "set xlabel 'relative density Dr [%]'", "set ylabel 'q [kPa]'",
             "set xrange [55:95]", "set yrange [0:2600]",
             f"set title {gp_quoted(f'The six Kimura tests with micropolar rotations, lc = {DEFAULT_LENGTH:g} m, cell {h:g} m (graded grid)')}"]
    series = []
    for side, colour in (("V", "#0072b2"), ("H", "#d55e00")):
        tests = sorted((t for t in runs if t.startswith(side)), key=lambda t: density[t])
        series += [(f"{side}: first peak", [(density[t], runs[t]["q_first_peak_kPa"]) for t in tests if runs[t]["q_first_peak_kPa"]],
                    f"linespoints lw 2 pt 7 lc rgb '{colour}'"),
                   (f"{side}: largest load to S/B 0.2", [(density[t], runs[t]["q_ult_kPa"]) for t in tests],
                    f"linespoints lw 2 dt 2 pt 6 lc rgb '{colour}'"),
                   (f"{side}: Kimura et al. (1985)", [measured[t] for t in measured if t.startswith(side)],
                    f"points pt 5 ps 1.6 lc rgb '{colour}'")]
    series = [x for x in series if x[1]]
    lines.append("plot " + ", ".join(f"'-' using 1:2 with {style} title {gp_quoted(t)}" for t, _, style in series))
    lines += ["\n".join(f"{x} {y}" for x, y in pts) + "\ne" for _, pts, _ in series]
    subprocess.run(["gnuplot"], input="\n".join(lines) + "\n", text=True, check=False)
    pairs = [(v, hz) for v in runs for hz in runs if v.startswith("V") and hz.startswith("H")
             and abs(density[v] - density[hz]) < 6]
    pairs.sort(key=lambda p: -density[p[0]])
    lines = [f"set terminal pngcairo size {600 * len(pairs)},520 noenhanced", "set datafile separator ','",
             "set datafile commentschars '#'", f"set output {gp_quoted(os.path.join(out, 'kimura_six_curves.png'))}",
             f"set multiplot layout 1,{len(pairs)}", "set grid", "set key bottom right", "set xlabel 'S/B'",
             "set ylabel 'q = V/B [kPa]'", "set xrange [0:0.2]", "set yrange [0:2600]"]
    for pair in pairs:
        plots = []
        for t, colour in zip(pair, ("#0072b2", "#d55e00")):
            plots.append(f"{gp_quoted(os.path.join(out, runs[t]['case'] + '_load.csv'))} using 'S_over_B':'q_kPa' with lines lw 2 "
                         f"lc rgb '{colour}' title {gp_quoted(f'{t} (Dr {density[t]:g} %)')}")
            lab = os.path.join(ROOT, "data", "lab", "kimura_1985", t + ".csv")
            if os.path.isfile(lab):
                plots.append(f"{gp_quoted(lab)} using 'S_over_B':'q_kPa' with points pt 7 ps 0.5 lc rgb '{colour}' "
                             f"title {gp_quoted('Kimura et al. (1985) ' + t)}")
        lines += [f"set title {gp_quoted(f'{pair[0]} and {pair[1]}: cell {h:g} m, lc = {DEFAULT_LENGTH:g} m')}",
                  "plot " + ", ".join(plots)]
    lines += ["unset multiplot", ""]
    subprocess.run(["gnuplot"], input="\n".join(lines), text=True, check=False)


if __name__ == "__main__":
    main()
