#!/usr/bin/env python3
"""How fast the fabric turns, from the bedding series of Lam & Tatsuoka (1988) (docs/calibration.md,
"The fabric's rate from the bedding series"; results in bench/results/lt88_fabric_closing/).

Their drained triaxial tests at 98 kPa with the load at omega = 0, 30, 60 and 90 deg to the
deposition direction (Fig. 5a, data/lab/lam_tatsuoka_1988/) run to 14-17 % axial strain. Between
6 and 12 % the gap in sigma1/sigma3 between omega 0 and 90 closes to 0.56 of itself, and between
30 and 90 to 0.35: the bedding's effect fades as the sand strains. Two things close it, the
fabric turning toward the load (at the rate k_f) and the specimens' densities converging on the
critical state; with k_f = 0 the model keeps only the second, so the driver separates the two.
For each k_f the four tests run once with the delivered set (its other values unchanged), and the
closing ratios gap(12 %) / gap(6 %) of the simulated curves are set beside the measured ones.

  python3 studies/lt88_fabric_closing.py [--out DIR] [--set PARAMETERS.json] [--tool build/calibration/acst_fit] K_F ...
(--set: the parameter set whose k_f is replaced; default the delivered one)
Writes OUT/closing.csv (k_f, the simulated and measured gaps at 6 and 12 % and their ratios,
for omega 0 - 90 and 30 - 90) and OUT/closing.png.
"""
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from calibration_runs import points, run_prediction  # noqa: E402
from footing_common import gp_quoted, tool_arguments, value_at, write_table  # noqa: E402

TESTS = {0: "lt88_fig5a_w00_hw1p0", 30: "lt88_fig5a_w30_hw1p0", 60: "lt88_fig5a_w60_hw1p0", 90: "lt88_fig5a_w90_hw1p0"}
STRAINS = (6.0, 12.0)


DELIVERED = os.path.join(ROOT, "data", "parameters", "toyoura_acst_calibrated.json")


def closing_run(k_f, out, parameter_set, tool):
    """The four tests run with `parameter_set`'s k_f replaced; returns the report's folder."""
    with open(os.path.join(ROOT, "data", "calibration", "toyoura_acst_fit.json")) as f:
        fit = json.load(f)
    experiments = [dict(e, data=os.path.normpath(os.path.join(ROOT, "data", "calibration", e["data"])))
                   for e in fit["experiments"] if any(t in e["data"] for t in TESTS.values())]
    d = {"name": "lt88_closing", "description": f"the bedding series with k_f = {k_f:g}", "parameters": {},
         "defaults": fit["defaults"], "experiments": experiments, "optimizer": {"design_points": 0, "starts": 1}}
    return run_prediction(os.path.join(out, f"k_f_{k_f:g}".replace(".", "p")), d, parameter_set, {"k_f": k_f}, tool,
                          f"k_f {k_f:g}")


def stress_ratio_curves(report):
    """{omega: (eps_a %, measured, simulated)} of the stress ratio (series 0)."""
    out = {}
    for omega, test in TESTS.items():
        rows = [r for r in points(report, test) if r["series"] == "0"]
        out[omega] = ([float(r["eps_a_pct"]) for r in rows], [float(r["measured"]) for r in rows],
                      [float(r["simulated"]) for r in rows])
    return out


def closings(curves):
    """The simulated and measured gaps in sigma1/sigma3 between omega 0 (and 30) and 90 at 6 and
    12 % axial strain and their closing ratios gap(12 %) / gap(6 %), from stress_ratio_curves."""
    row = {}
    for source, k in (("simulated", 2), ("measured", 1)):
        for low in (0, 30):
            gaps = [value_at(curves[low][0], curves[low][k], e) - value_at(curves[90][0], curves[90][k], e)
                    for e in STRAINS]
            row[f"{source}_gap_{low}_90_at_6pct"] = round(gaps[0], 4)
            row[f"{source}_gap_{low}_90_at_12pct"] = round(gaps[1], 4)
            row[f"{source}_closing_{low}_90"] = round(gaps[1] / gaps[0], 3)
    return row


def main():
    a = tool_arguments(__doc__, "lt88_fabric_closing", "calibration/acst_fit",
                       [("--set", {"default": DELIVERED, "help": "the parameter set whose k_f is replaced"}),
                        ("k_f", {"nargs": "+", "type": float})])
    table = []
    for k_f in a.k_f:
        if not 0.0 <= k_f <= 100.0:
            sys.exit(f"k_f {k_f:g} is out of range; allowed: [0, 100]")
        row = {"k_f": k_f}
        row.update(closings(stress_ratio_curves(closing_run(k_f, a.out, os.path.abspath(a.set), a.tool))))
        table.append(row)
        print(json.dumps(row), flush=True)
    write_table(os.path.join(a.out, "closing.csv"), list(table[0]), table)
    pts = lambda key: "\n".join(f"{r['k_f']} {r[key]}" for r in table) + "\ne"
    gp = ["set terminal pngcairo size 900,600 noenhanced", f"set output {gp_quoted(os.path.join(a.out, 'closing.png'))}",
          "set grid", "set key top right", "set xlabel 'k_f (the fabric rate)'",
          "set ylabel 'gap in sigma1/sigma3 at 12 % over the gap at 6 % axial strain'",
          "set title 'Lam & Tatsuoka (1988) at 98 kPa: how the bedding gap closes'",
          "plot '-' using 1:2 with linespoints lw 2 pt 7 title 'simulated, omega 0 - 90', "
          "'-' using 1:2 with linespoints lw 2 pt 5 title 'simulated, omega 30 - 90', "
          f"{table[0]['measured_closing_0_90']} with lines dt 2 lw 2 title 'measured, omega 0 - 90', "
          f"{table[0]['measured_closing_30_90']} with lines dt 3 lw 2 title 'measured, omega 30 - 90'",
          pts("simulated_closing_0_90"), pts("simulated_closing_30_90"), ""]
    subprocess.run(["gnuplot"], input="\n".join(gp), text=True, check=False)


if __name__ == "__main__":
    main()
