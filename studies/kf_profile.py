#!/usr/bin/env python3
"""What the element data allow for the fabric's rate k_f: the delivered fit repeated with k_f held
at each value asked (docs/calibration.md, "The fabric's rate profiled over the fit"; results in
bench/results/kf_profile/).

For each k_f, data/calibration/toyoura_acst_fit.json is fitted with k_f fixed there and every
other fitted value free, as delivered. Each fitted set (its Tatsuoka F0) is then judged on what
the fit does not see: the 78 peaks of Fukushima & Tatsuoka's Table 1 (the mean of simulated minus
measured phi, over all rows and over sigma3' >= 9 kPa, where the membrane's share is small) and
the closing of Lam & Tatsuoka's bedding gap between 6 and 12 % axial strain
(lt88_fabric_closing.py), the measure that turns the fabric most.

  python3 studies/kf_profile.py [--out DIR] [--fit DESCRIPTION.json] [--tool build/calibration/acst_fit] K_F ...
(--fit: the description to profile; default the delivered one. With toyoura_acst_closing_fit.json
the fit itself holds the closings, "The closing in the fit".)
Writes OUT/profile.csv (k_f, the fit's objective and each fold's pooled RMS/scale as fitted, the
fitted values, the Table 1 biases, the closings) and OUT/profile.png.
"""
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from calibration_runs import TABLE1, peak_rows  # noqa: E402
from footing_common import gp_quoted, tool_arguments, write_table  # noqa: E402
from lt88_fabric_closing import closing_run, closings, stress_ratio_curves  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CALIBRATION = os.path.join(ROOT, "data", "calibration")
FIT = os.path.join(CALIBRATION, "toyoura_acst_fit.json")
REPORTED = ["F0[tatsuoka]", "e_A", "n", "d1", "m", "h1", "c"]


def tag_of(k_f):
    return f"k_f_{k_f:g}".replace(".", "p")


def fit_at(k_f, out, tool, description=FIT):
    """The description fitted with k_f fixed: (report dict, its folds, the Tatsuoka set's path)."""
    with open(description) as f:
        d = json.load(f)
    here = os.path.dirname(os.path.abspath(description))
    absolute = lambda name: os.path.normpath(os.path.join(here, name))
    for e in d["experiments"]:
        e["data"] = [absolute(n) for n in e["data"]] if isinstance(e["data"], list) else absolute(e["data"])
    d["material"]["parameters"]["k_f"] = k_f
    del d["parameters"]["k_f"]
    folds = d.pop("cross_validation")["folds"]
    d["name"] = tag_of(k_f)
    d["description"] = f"{os.path.basename(description)} with k_f held at {k_f:g} (studies/kf_profile.py)."
    directory = os.path.join(out, tag_of(k_f), "fit")
    d["output"] = dict(d["output"], directory=directory)
    os.makedirs(os.path.dirname(directory), exist_ok=True)
    path = os.path.join(out, tag_of(k_f), "fit_description.json")
    with open(path, "w") as f:
        json.dump(d, f, indent=1)
    run = subprocess.run([tool, path], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"k_f {k_f:g}: acst_fit failed: {run.stderr.strip()}")
    with open(os.path.join(directory, d["name"] + "_report.json")) as f:
        report = json.load(f)
    return report, folds, os.path.join(directory, d["name"] + "_parameters_tatsuoka.json")


def pooled(report, ids):
    """The pooled RMS of (simulated - measured) / scale over the experiments' points."""
    num = den = 0.0
    for e in report["experiments"]:
        if e["id"] in ids:
            for a in e["axes"]:
                num += a["points"] * a["rms_normalised"] ** 2
                den += a["points"]
    return math.sqrt(num / den) if den else float("nan")


def table1_biases(parameter_set, out, tool, k_f):
    rows = [(s, sim - meas) for s, _, meas, sim in
            peak_rows(os.path.join(out, tag_of(k_f), "table1"), TABLE1, parameter_set, {}, tool, f"k_f {k_f:g}")]
    mean = lambda v: sum(v) / len(v)
    high = [d for s, d in rows if s >= 9.0]
    return {"table1_rows": len(rows), "table1_bias_deg": round(mean([d for _, d in rows]), 2),
            "table1_mean_abs_deg": round(mean([abs(d) for _, d in rows]), 2),
            "table1_bias_deg_sigma3_ge_9": round(mean(high), 2)}


def figure(path, table, title, closing_fitted):
    pts = lambda key: "\n".join(f"{r['k_f']} {r[key]}" for r in table) + "\ne"
    m = table[0]
    gp = ["set terminal pngcairo size 1500,500 noenhanced", f"set output {gp_quoted(path)}", "set grid",
          f"set multiplot layout 1,3 title {gp_quoted(title)}",
          "set xlabel 'k_f (the fabric rate, held)'",
          "set ylabel 'objective (sum of weighted squares)'", "set title 'the fit'",
          "plot '-' using 1:2 with linespoints lw 2 pt 7 notitle", pts("objective"),
          "set ylabel 'gap(12 %) / gap(6 %) in sigma1/sigma3'",
          f"set title 'Lam & Tatsuoka bedding gap closing{'' if closing_fitted else ' (not fitted)'}'",
          "set key bottom left",
          "plot '-' using 1:2 with linespoints lw 2 pt 7 title 'omega 0 - 90', "
          "'-' using 1:2 with linespoints lw 2 pt 5 title 'omega 30 - 90', "
          f"{m['measured_closing_0_90']} with lines dt 2 lw 2 title 'measured, omega 0 - 90', "
          f"{m['measured_closing_30_90']} with lines dt 3 lw 2 title 'measured, omega 30 - 90'",
          pts("simulated_closing_0_90"), pts("simulated_closing_30_90"),
          "set ylabel 'phi simulated - measured, deg'", "set title 'Fukushima & Tatsuoka Table 1 peaks (not fitted)'",
          "set key bottom right",
          "plot '-' using 1:2 with linespoints lw 2 pt 7 title 'mean, 78 rows', "
          "'-' using 1:2 with linespoints lw 2 pt 5 title 'mean, sigma3 >= 9 kPa', 0 with lines lc 'black' notitle",
          pts("table1_bias_deg"), pts("table1_bias_deg_sigma3_ge_9"), "unset multiplot", ""]
    subprocess.run(["gnuplot"], input="\n".join(gp), text=True, check=False)


def main():
    a = tool_arguments(__doc__, "kf_profile", "calibration/acst_fit",
                       [("--fit", {"default": FIT, "help": "the fit description to profile (default: the delivered one)"}),
                        ("k_f", {"nargs": "+", "type": float})])
    a.fit = os.path.abspath(a.fit)
    with open(a.fit) as f:
        closing_fitted = any(e.get("test") == "gap_closing" for e in json.load(f)["experiments"])
    table = []
    for k_f in a.k_f:
        if not 0.0 <= k_f <= 40.0:
            sys.exit(f"k_f {k_f:g} is out of range; allowed: [0, 40] (the fit's bounds)")
        report, folds, parameter_set = fit_at(k_f, a.out, a.tool, a.fit)
        values = {p["label"]: p["value"] for p in report["parameters"]}
        row = {"k_f": k_f, "objective": round(report["objective"]["sum_of_squares"], 5),
               "fit_s": round(report["time"]["total_s"], 1)}
        row.update({f"fitted_{fold}": round(pooled(report, set(ids)), 3) for fold, ids in folds.items()})
        row.update({k: round(values[k], 4) for k in REPORTED if k in values})
        row.update(table1_biases(parameter_set, a.out, a.tool, k_f))
        closing = closing_run(k_f, os.path.join(a.out, tag_of(k_f)), parameter_set, a.tool)
        row.update(closings(stress_ratio_curves(closing)))
        print(json.dumps(row), flush=True)
        table.append(row)
    write_table(os.path.join(a.out, "profile.csv"), list(table[0]), table)
    which = "the delivered fit" if a.fit == FIT else os.path.basename(a.fit)
    figure(os.path.join(a.out, "profile.png"), table, f"{which} with k_f held (Toyoura sand, ACST)", closing_fitted)


if __name__ == "__main__":
    main()
