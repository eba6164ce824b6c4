#!/usr/bin/env python3
"""The dense Kimura pair over the fabric's rate that the element data allow (docs/footing-study.md,
"The footing over the fabric's rate"; results in bench/results/footing_kf_interval/).

V85.6 and H86.7 run with the regularised sand on the graded grid (footing_regularised.py's cases,
one cell size, to one S/B) with each parameter set given: the closing candidate's fitted set
(docs/calibration.md, "The closing in the fit"), the sets fitted with k_f held at the ends of
its interval (bench/results/kf_profile_closing/sets/), and the delivered set, whose runs of the
same case are read from bench/results/footing_regularised/convergence.csv (not run again; their
load curves are not kept). Nothing here chooses a set: the footing is measured over what the
element data allow. Cases already in OUT are not run again. Writes OUT/interval.csv (one row per
set: its k_f, V's and H's first peak and largest load to the stop, q_H / q_V of both, against
the centrifuge's 0.89), OUT/curves.csv (the runs' load curves, decimated) and OUT/interval.png
(the ratio against k_f, and the load curves).

  python3 bench/studies/footing_kf_interval.py [--out DIR] [--h 0.03] [--stop 0.2] [--threads 2] [LABEL=SET ...]
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
from footing_common import ROOT, gp_quoted, read_curve, write_table  # noqa: E402
from footing_regularised import parse_case  # noqa: E402

DEFAULT_SETS = [
    ("k_f held at 0.7 (lower end of the interval)", "bench/results/kf_profile_closing/sets/closing_kf0p7.json"),
    ("fitted with the closings (k_f 3.85)", "data/calibration/reports/toyoura_acst_closing/toyoura_acst_closing_parameters_tatsuoka.json"),
    ("k_f held at 7 (near the upper end)", "bench/results/kf_profile_closing/sets/closing_kf7.json"),
    ("delivered (k_f 8.67)", "acst"),
]
KIMURA = {"V85.6": 1953.0, "H86.7": 1734.0}  # q_ult, kPa (data/lab/kimura_1985/)
MEASURED_RATIO = KIMURA["H86.7"] / KIMURA["V85.6"]
RECORDED = os.path.join(ROOT, "bench", "results", "footing_regularised", "convergence.csv")
FIELDS = ["set", "file", "k_f", "V_first_peak_kPa", "V_q_max_kPa", "H_first_peak_kPa", "H_q_max_kPa",
          "ratio_first_peaks", "ratio_q_max", "measured_ratio"]


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


def case_text(test, h, set_file):
    return f"{test},h={h:g},grid=graded" + ("" if set_file == "acst" else f",set={set_file}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "results", "footing_kf_interval"))
    ap.add_argument("--h", type=float, default=0.03, help="the window's cell, m")
    ap.add_argument("--stop", type=float, default=0.2, help="S/B to run to")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("sets", nargs="*", help="LABEL=SET (default: the four sets above)")
    a = ap.parse_args()
    sets = [tuple(s.split("=", 1)) for s in a.sets] or DEFAULT_SETS
    for label, _ in sets:
        if not re.fullmatch(r"[A-Za-z0-9 _.,()+-]+", label):
            sys.exit(f"label {label!r}: letters, digits, spaces and _.,()+- only")
    cases = [case_text(t, a.h, f) for _, f in sets if f != "acst" for t in ("V85.6", "H86.7")]
    subprocess.run([sys.executable, os.path.join(os.path.dirname(os.path.abspath(__file__)), "footing_regularised.py"),
                    "--out", a.out, "--threads", str(a.threads), "--stop", str(a.stop)] + cases, check=True)
    with open(os.path.join(a.out, "convergence.csv")) as f:
        done = {r["case"]: r for r in csv.DictReader(f)}
    with open(RECORDED) as f:  # the delivered set's runs, under the name they were recorded with
        recorded = {r["case"].replace("_window3_graded", "_graded"): r for r in csv.DictReader(f) if r["set"] == "acst"}
    rows, curves = [], []
    for label, set_file in sets:
        row = {"set": label, "file": set_file, "k_f": round(k_f_of(set_file), 4), "measured_ratio": round(MEASURED_RATIO, 3)}
        for test in ("V85.6", "H86.7"):
            name = parse_case(case_text(test, a.h, set_file))["name"]
            r = recorded.get(name) if set_file == "acst" else done.get(name)
            # A recorded run that stopped past the stop still holds its largest load up to it.
            finished = r and (r["status"] == "done" or float(r["final_S_over_B"] or 0) >= a.stop)
            if not finished or float(r["S_ult_over_B"]) > a.stop:
                sys.exit(f"{name}: no run to S/B {a.stop:g} ({r['status'] if r else 'missing'})")
            row[f"{test[0]}_first_peak_kPa"] = float(r["q_first_peak_kPa"] or "nan")
            row[f"{test[0]}_q_max_kPa"] = float(r["q_ult_kPa"])
            if set_file != "acst":
                S, q = read_curve(os.path.join(a.out, name, "load_settlement.csv"))
                curves.append((label, test, decimated(S, q)))
        row["ratio_first_peaks"] = round(row["H_first_peak_kPa"] / row["V_first_peak_kPa"], 3)
        row["ratio_q_max"] = round(row["H_q_max_kPa"] / row["V_q_max_kPa"], 3)
        rows.append(row)
        print(json.dumps(row), flush=True)
    write_table(os.path.join(a.out, "interval.csv"), FIELDS, rows)
    write_table(os.path.join(a.out, "curves.csv"), ["set", "test", "S_over_B", "q_kPa"],
                [{"set": label, "test": test, "S_over_B": round(x, 5), "q_kPa": round(y, 1)}
                 for label, test, pts in curves for x, y in pts])
    pts = lambda key: "\n".join(f"{r['k_f']} {r[key]}" for r in sorted(rows, key=lambda r: r["k_f"])) + "\ne"
    gp = ["set terminal pngcairo size 1500,560 noenhanced", f"set output {gp_quoted(os.path.join(a.out, 'interval.png'))}",
          "set multiplot layout 1,2", "set grid", "set key top left",
          "set title 'Kimura dense pair: q_H / q_V against the fabric rate'", "set xlabel 'k_f of the set'",
          "set ylabel 'q_H / q_V'", "set yrange [0.6:1.4]",
          "plot '-' using 1:2 with linespoints lw 2 pt 7 title 'largest loads', "
          "'-' using 1:2 with linespoints lw 2 pt 5 title 'first peaks', "
          f"{MEASURED_RATIO} with lines dt 2 lw 2 lc 'black' title 'centrifuge (1734 / 1953)'",
          pts("ratio_q_max"), pts("ratio_first_peaks"),
          "set yrange [0:*]", "set key bottom right font ',8'",
          f"set title {gp_quoted(f'the load curves (regularised, graded grid, h = {a.h:g} m)')}",
          "set xlabel 'S/B'", "set ylabel 'q [kPa]'",
          "plot " + ", ".join(f"'-' using 1:2 with lines lw 2 dt {1 if test == 'V85.6' else 2} lc {1 + k // 2} "
                              f"title {gp_quoted(test + ', ' + label)}" for k, (label, test, _) in enumerate(curves))]
    for _, _, points in curves:
        gp += [f"{x} {y}" for x, y in points] + ["e"]
    gp += ["unset multiplot", ""]
    subprocess.run(["gnuplot"], input="\n".join(gp), text=True, check=False)


if __name__ == "__main__":
    main()
