#!/usr/bin/env python3
"""The Kimura pairs over the fabric's rate that the element data allow (docs/footing-study.md,
"The footing over the fabric's rate"; results in bench/results/footing_kf_interval/ and, with the
micropolar rotations at the three densities, bench/results/footing_kf_interval_micropolar/).

V and H run on the graded grid (one cell size, to one S/B) with each parameter set given: the
closing candidate's fitted set (docs/calibration.md, "The closing in the fit"), the sets fitted
with k_f held at the ends of its interval (bench/results/kf_profile_closing/sets/), and the
delivered set, whose runs of the same case are read from the regularisation's own recorded table
(not run again). The sand is regularised either by the averaged void ratio at its default length
(footing_regularised.py's cases; the delivered runs from bench/results/footing_regularised/) or,
with --micropolar RUNS, by the core's micropolar rotations at their default length
(footing_micropolar.py's cases, run in RUNS; the delivered runs from
bench/results/footing_micropolar/). --pairs all takes the three density pairs of the reference
study's kimura group, V85.6-H86.7, V75.1-H76.5 and V64.6-H61.0; the centrifuge's ratio is in
data/lab/kimura_1985/ for the dense pair only. Nothing here chooses a set: the footing is measured
over what the element data allow. Cases already run are not run again. Writes OUT/interval.csv
(one row per set and pair: its k_f, V's and H's first peak, largest load to the stop and, for the
micropolar runs, mean over S/B 0.08-0.2, and q_H / q_V of each), OUT/curves.csv (the runs' load
curves, decimated) and OUT/interval.png (the ratios against k_f, and the load curves per pair).

  python3 studies/footing_kf_interval.py [--out DIR] [--h 0.03] [--stop 0.2] [--threads 2]
      [--micropolar RUNS] [--pairs dense|all] [LABEL=SET ...]
  (SET: acst for the delivered set's recorded runs, or a material file relative to the repository;
  default the four above)
"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import footing_micropolar as fm  # noqa: E402
from footing_common import ROOT, gp_quoted, read_curve, write_table  # noqa: E402
from footing_regularised import parse_case  # noqa: E402

DEFAULT_SETS = [
    ("k_f held at 0.7 (lower end of the interval)", "bench/results/kf_profile_closing/sets/closing_kf0p7.json"),
    ("fitted with the closings (k_f 3.85)", "data/calibration/reports/toyoura_acst_closing/toyoura_acst_closing_parameters_tatsuoka.json"),
    ("k_f held at 7 (near the upper end)", "bench/results/kf_profile_closing/sets/closing_kf7.json"),
    ("delivered (k_f 8.67)", "acst"),
]
PAIRS = {"dense": [("V85.6", "H86.7")], "all": [("V85.6", "H86.7"), ("V75.1", "H76.5"), ("V64.6", "H61.0")]}
MEASURED = fm.measured_peaks()  # {test: (D_r, q_peak)}: the dense pair only
RESULTS = os.path.join(ROOT, "bench", "results")
FIELDS = ["set", "file", "k_f", "pair", "V_first_peak_kPa", "V_q_max_kPa", "V_mean_kPa", "H_first_peak_kPa", "H_q_max_kPa",
          "H_mean_kPa", "ratio_first_peaks", "ratio_q_max", "ratio_mean", "measured_ratio"]


def k_f_of(set_file):
    path = os.path.join(ROOT, "data", "parameters", "toyoura_acst_calibrated.json") if set_file == "acst" \
        else os.path.join(ROOT, set_file)
    with open(path) as f:
        return json.load(f)["parameters"]["k_f"]


def decimated(S, q, step=0.002):
    """The load curve at about every `step` of S/B, with its largest load kept."""
    top = max(range(len(q)), key=lambda i: q[i])
    out, last = [], -1.0
    for i, (x, y) in enumerate(zip(S, q)):
        if x - last >= step or i == top or i == len(S) - 1:
            out.append((x, y))
            last = x
    return out


class Averaged:
    """The averaged void ratio at its default length (footing_regularised.py)."""
    recorded = os.path.join(RESULTS, "footing_regularised", "convergence.csv")

    def __init__(self, a):
        self.a = a

    def text(self, test, set_file):
        return f"{test},h={self.a.h:g},grid=graded" + ("" if set_file == "acst" else f",set={set_file}")

    def name(self, test, set_file):
        return parse_case(self.text(test, set_file))["name"]

    def run(self, cases):
        subprocess.run([sys.executable, os.path.join(os.path.dirname(os.path.abspath(__file__)), "footing_regularised.py"),
                        "--out", self.a.out, "--threads", str(self.a.threads), "--stop", str(self.a.stop)] + cases, check=True)

    def delivered(self):  # under the name they were recorded with
        with open(self.recorded) as f:
            return {r["case"].replace("_window3_graded", "_graded"): r for r in csv.DictReader(f) if r["set"] == "acst"}

    def curve(self, name, set_file):  # the delivered runs' load curves are not kept
        return None if set_file == "acst" else read_curve(os.path.join(self.a.out, name, "load_settlement.csv"))


class Micropolar(Averaged):
    """The local sand with the core's micropolar rotations at their default length (footing_micropolar.py)."""
    recorded = os.path.join(RESULTS, "footing_micropolar", "convergence.csv")

    def text(self, test, set_file):
        return f"{test},h={self.a.h:g}" + ("" if set_file == "acst" else f",set={set_file}")

    def name(self, test, set_file):
        return fm.case_of(self.text(test, set_file))["name"]

    def run(self, cases):
        subprocess.run([sys.executable, os.path.join(os.path.dirname(os.path.abspath(__file__)), "footing_micropolar.py"),
                        "--runs", self.a.micropolar, "--out", self.a.out, "--threads", str(self.a.threads),
                        "--stop", str(self.a.stop)] + cases, check=True)

    def delivered(self):
        with open(self.recorded) as f:
            return {r["case"]: r for r in csv.DictReader(f)}

    def curve(self, name, set_file):
        return read_curve(os.path.join(os.path.dirname(self.recorded) if set_file == "acst" else self.a.out, name + "_load.csv"))


def number(text):
    return float(text) if text not in (None, "", "nan") else None


def ratio(h, v):
    return round(h / v, 3) if h and v else None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "footing_kf_interval"))
    ap.add_argument("--h", type=float, default=0.03, help="the window's cell, m")
    ap.add_argument("--stop", type=float, default=0.2, help="S/B to run to")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--micropolar", metavar="RUNS", help="the micropolar rotations instead of the averaged void ratio; "
                    "RUNS: the folder of the runs (large: VTK frames)")
    ap.add_argument("--pairs", choices=sorted(PAIRS), default="dense", help="the dense pair, or all three density pairs")
    ap.add_argument("sets", nargs="*", help="LABEL=SET (default: the four sets above)")
    a = ap.parse_args()
    sets = [tuple(s.split("=", 1)) for s in a.sets] or DEFAULT_SETS
    for label, _ in sets:
        if not re.fullmatch(r"[A-Za-z0-9 _.,()+-]+", label):
            sys.exit(f"label {label!r}: letters, digits, spaces and _.,()+- only")
    way = Micropolar(a) if a.micropolar else Averaged(a)
    pairs = PAIRS[a.pairs]
    way.run([way.text(t, f) for _, f in sets if f != "acst" for pair in pairs for t in pair])
    with open(os.path.join(a.out, "convergence.csv")) as f:
        done = {r["case"]: r for r in csv.DictReader(f)}
    recorded = way.delivered()
    rows, curves = [], []
    for label, set_file in sets:
        for pair in pairs:
            row = {"set": label, "file": set_file, "k_f": round(k_f_of(set_file), 4), "pair": "-".join(pair)}
            for test in pair:
                name = way.name(test, set_file)
                r = recorded.get(name) if set_file == "acst" else done.get(name)
                # A recorded run that stopped past the stop still holds its largest load up to it.
                finished = r and (r["status"] == "done" or float(r["final_S_over_B"] or 0) >= a.stop)
                if not finished or float(r["S_ult_over_B"]) > a.stop:
                    sys.exit(f"{name}: no run to S/B {a.stop:g} ({r['status'] if r else 'missing'})")
                row[f"{test[0]}_first_peak_kPa"] = number(r["q_first_peak_kPa"])
                row[f"{test[0]}_q_max_kPa"] = float(r["q_ult_kPa"])
                row[f"{test[0]}_mean_kPa"] = number(r.get("q_mean_SB0.08_0.2_kPa"))
                curve = way.curve(name, set_file)
                if curve:
                    curves.append((label, test, "-".join(pair), decimated(*curve)))
            for key, quantity in (("first_peaks", "first_peak"), ("q_max", "q_max"), ("mean", "mean")):
                row["ratio_" + key] = ratio(row[f"H_{quantity}_kPa"], row[f"V_{quantity}_kPa"])
            if all(t in MEASURED for t in pair):
                row["measured_ratio"] = round(MEASURED[pair[1]][1] / MEASURED[pair[0]][1], 3)
            rows.append(row)
            print(json.dumps(row), flush=True)
    write_table(os.path.join(a.out, "interval.csv"), FIELDS, rows)
    write_table(os.path.join(a.out, "curves.csv"), ["set", "test", "S_over_B", "q_kPa"],
                [{"set": label, "test": test, "S_over_B": round(x, 5), "q_kPa": round(y, 1)}
                 for label, test, _, pts in curves for x, y in pts])
    figure(a, way, pairs, rows, curves)


def figure(a, way, pairs, rows, curves):
    """q_H / q_V against k_f (one line per pair and measure; the centrifuge's dense ratio), and one
    panel of load curves per pair."""
    panels = 1 + len(pairs)
    columns = 2 if panels > 2 else panels
    layout = ((panels + columns - 1) // columns, columns)
    measures = [("ratio_q_max", "largest loads", 7, 1), ("ratio_first_peaks", "first peaks", 5, 3)]
    if any(r["ratio_mean"] for r in rows):
        measures.append(("ratio_mean", "means over S/B 0.08-0.2", 9, 2))
    plots, data = [], []
    for k, pair in enumerate(pairs):
        for key, what, pt, dt in measures:
            pts = sorted((r["k_f"], r[key]) for r in rows if r["pair"] == "-".join(pair) and r[key])
            if pts:
                plots.append(f"'-' using 1:2 with linespoints lw 2 pt {pt} dt {dt} lc {k + 1} "
                             f"title {gp_quoted(f'{pair[1]} / {pair[0]}: {what}')}")
                data.append("\n".join(f"{x} {y}" for x, y in pts) + "\ne")
    dense = [r["measured_ratio"] for r in rows if r.get("measured_ratio")]
    if dense:
        plots.append(f"{dense[0]} with lines dt 2 lw 2 lc 'black' title "
                     f"{gp_quoted(f'centrifuge, dense pair ({MEASURED[pairs[0][1]][1]:.0f} / {MEASURED[pairs[0][0]][1]:.0f})')}")
    sand = "micropolar rotations" if isinstance(way, Micropolar) else "averaged void ratio"
    gp = [f"set terminal pngcairo size {750 * layout[1]},{560 * layout[0]} noenhanced",
          f"set output {gp_quoted(os.path.join(a.out, 'interval.png'))}",
          f"set multiplot layout {layout[0]},{layout[1]}", "set grid", "set key top left font ',9'",
          f"set title {gp_quoted(f'Kimura pairs: q_H / q_V against the fabric rate ({sand}, h = {a.h:g} m)')}",
          "set xlabel 'k_f of the set'", "set ylabel 'q_H / q_V'", "set yrange [0.6:1.6]",
          "plot " + ", ".join(plots)] + data
    gp += ["set yrange [0:*]", "set key bottom right font ',8'", "set xlabel 'S/B'", "set ylabel 'q [kPa]'"]
    for pair in pairs:
        mine = [(label, test, pts) for label, test, p, pts in curves if p == "-".join(pair)]
        labels = list(dict.fromkeys(label for label, _, _ in mine))
        gp += [f"set title {gp_quoted(f'{pair[0]} and {pair[1]}: the load curves ({sand}, graded grid, h = {a.h:g} m)')}",
               "plot " + ", ".join(f"'-' using 1:2 with lines lw 2 dt {1 if test == pair[0] else 2} lc {1 + labels.index(label)} "
                                   f"title {gp_quoted(test + ', ' + label)}" for label, test, _ in mine)]
        for _, _, points in mine:
            gp += [f"{x} {y}" for x, y in points] + ["e"]
    gp += ["unset multiplot", ""]
    subprocess.run(["gnuplot"], input="\n".join(gp), text=True, check=False)


if __name__ == "__main__":
    main()
