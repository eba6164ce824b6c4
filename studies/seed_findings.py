#!/usr/bin/env python3
"""The reference study's findings side by side (issue 76 item 4): what the reference study (the
seed) states, the local model's recorded study at 0.09 m, the converged study and Kimura et al.'s
(1985) centrifuge, one row per quantity. The seed's paper gives most findings as trends in words
and figures, not tables: its column holds the claim as the sweep description states it
(data/sweeps/reference_study.json, "findings"), with a number where the paper gives one.

  python3 studies/seed_findings.py [--local DIR] [--converged DIR] [--out DIR]
Reads each folder's table.json (a case not run yet reads "pending", a column its record predates
"not recorded"); writes OUT/seed_findings.md
and OUT/seed_findings.json (the same rows).
"""
import argparse
import json
import math
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
KIMURA = {"V85.6": (1952.7, 0.0906), "H86.7": (1733.8, 0.163)}  # data/lab/kimura_1985/tests_meta.csv
BEDDING = ["V85.6", "bedding_20", "bedding_45", "bedding_70", "bedding_90"]
SIDES = ["sheared_area_left_at_end_m2", "sheared_area_right_at_end_m2"]


def table(folder):
    with open(os.path.join(folder, "table.json")) as f:
        return {r["case"]: r for r in json.load(f)["cases"] if r.get("status") == "done"}


def value(t, case, column):
    """None where the case has not run, NaN where its row lacks the column (an older record)."""
    if case not in t:
        return None
    v = t[case].get(column)
    return float(v) if isinstance(v, (int, float)) and math.isfinite(v) else math.nan


def shown(values, digits=0):
    """Values joined with ' / ': 'pending' for a case not run, 'not recorded' for a missing column."""
    return " / ".join("pending" if v is None else "not recorded" if math.isnan(v) else f"{v:.{digits}f}" for v in values)


def rows_of(t):
    """The quantities of one table, by name: lists of numbers (None where a case is missing)."""
    q = lambda cases, col="q_ult_kPa": [value(t, c, col) for c in cases]
    ratio = lambda a, b: None if a is None or b is None else a / b
    spread = lambda v: None if None in v else 100.0 * (max(v) - min(v)) / min(v) if all(map(math.isfinite, v)) else math.nan
    out = {
        "bedding q_ult": q(BEDDING),
        "bedding S_ult/B": q(BEDDING, "S_ult_over_B"),
        "bedding q at S/B 0.5, spread %": [spread(q(BEDDING, "q_at_S_over_B_0.5_kPa"))],
        "sheared left / right at S/B 0.5, bedding 20, 45, 70": [ratio(value(t, c, SIDES[0]), value(t, c, SIDES[1]))
                                                                 for c in ("bedding_20", "bedding_45", "bedding_70")],
        "isotropic / ACST, beta 10, 20, 30": [ratio(value(t, f"isotropic_beta{b}", "q_ult_kPa"), value(t, f"alpha0_beta{b}", "q_ult_kPa"))
                                              for b in (10, 20, 30)],
        "width 10.8, 12.6, 14.4 m: q_ult": q(["width_10.8", "V85.6", "width_14.4"]),
        "width 10.8, 12.6, 14.4 m: q at S/B 0.5": q(["width_10.8", "V85.6", "width_14.4"], "q_at_S_over_B_0.5_kPa"),
        "V85.6 / H86.7 q_ult": q(["V85.6", "H86.7"]),
        "V85.6 / H86.7 S_ult/B": q(["V85.6", "H86.7"], "S_ult_over_B"),
        "a = 1 - q_H86.7 / q_V85.6": [None if None in q(["V85.6", "H86.7"]) else 1.0 - value(t, "H86.7", "q_ult_kPa") / value(t, "V85.6", "q_ult_kPa")],
    }
    for alpha in (0, 45, 90):
        first = {0: "V85.6", 45: "bedding_45", 90: "bedding_90"}[alpha]
        out[f"bedding {alpha}: q_ult at beta 0, 10, 20, 30, 40"] = q([first] + [f"alpha{alpha}_beta{b}" for b in (10, 20, 30, 40)])
    def asymmetry(case):  # |A_left - A_right| / (A_left + A_right) at the peak (docs/sweeps.md, "The table")
        left, right = value(t, case, "sheared_area_left_at_peak_m2"), value(t, case, "sheared_area_right_at_peak_m2")
        return None if left is None else abs(left - right) / (left + right)
    out["sheared asymmetry at the peak, isotropic vs ACST, beta 10, 20, 30"] = [
        asymmetry(f"{m}_beta{b}") for b in (10, 20, 30) for m in ("isotropic", "alpha0")]
    return out


SEED = {  # the claim each row checks, as the description states it
    "bedding q_ult": "falls from 0 to 90 deg",
    "bedding S_ult/B": "grows from 0 to 90 deg",
    "bedding q at S/B 0.5, spread %": "hardly depends on the bedding",
    "sheared left / right at S/B 0.5, bedding 20, 45, 70": "asymmetric, the larger wedge on the left (> 1)",
    "isotropic / ACST, beta 10, 20, 30": "1.49 / 1.45 / 1.45",
    "width 10.8, 12.6, 14.4 m: q_ult": "the same",
    "width 10.8, 12.6, 14.4 m: q at S/B 0.5": "differs",
    "V85.6 / H86.7 q_ult": "(compared with the centrifuge)",
    "V85.6 / H86.7 S_ult/B": "(compared with the centrifuge)",
    "a = 1 - q_H86.7 / q_V85.6": "proposes i_alpha = 1 - a sin^2(alpha)",
    "bedding 0: q_ult at beta 0, 10, 20, 30, 40": "falls with beta",
    "bedding 45: q_ult at beta 0, 10, 20, 30, 40": "falls with beta, more at larger bedding",
    "bedding 90: q_ult at beta 0, 10, 20, 30, 40": "falls with beta, more at larger bedding",
    "sheared asymmetry at the peak, isotropic vs ACST, beta 10, 20, 30": "Fig. 23: the isotropic one more one-sided",
}
CENTRIFUGE = {
    "bedding q_ult": f"{KIMURA['V85.6'][0]:.0f} at 0 deg (Dr 85.6 %); {KIMURA['H86.7'][0]:.0f} at 90 (Dr 86.7 %)",
    "bedding S_ult/B": f"{KIMURA['V85.6'][1]:.3f} at 0 deg; {KIMURA['H86.7'][1]:.3f} at 90",
    "V85.6 / H86.7 q_ult": f"{KIMURA['V85.6'][0]:.0f} / {KIMURA['H86.7'][0]:.0f}",
    "V85.6 / H86.7 S_ult/B": f"{KIMURA['V85.6'][1]:.3f} / {KIMURA['H86.7'][1]:.3f}",
    "a = 1 - q_H86.7 / q_V85.6": f"{1.0 - KIMURA['H86.7'][0] / KIMURA['V85.6'][0]:.3f}",
}
DIGITS = {"bedding S_ult/B": 3, "V85.6 / H86.7 S_ult/B": 3, "a = 1 - q_H86.7 / q_V85.6": 3, "bedding q at S/B 0.5, spread %": 1,
          "sheared left / right at S/B 0.5, bedding 20, 45, 70": 2, "isotropic / ACST, beta 10, 20, 30": 2,
          "sheared asymmetry at the peak, isotropic vs ACST, beta 10, 20, 30": 2}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--local", default=os.path.join(ROOT, "data/sweeps/recorded/reference_study_local_0.09m"))
    ap.add_argument("--converged", default=os.path.join(ROOT, "data/sweeps/recorded/reference_study"))
    ap.add_argument("--out", default=os.path.join(ROOT, "bench/results/reference_study_findings"))
    a = ap.parse_args()
    local, converged = rows_of(table(a.local)), rows_of(table(a.converged))
    rows = [{"quantity": k, "seed": SEED[k], "local_0.09m": local[k], "converged": converged[k], "centrifuge": CENTRIFUGE.get(k, "")}
            for k in SEED]
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "seed_findings.json"), "w") as f:
        json.dump({"local": os.path.relpath(a.local, ROOT), "converged": os.path.relpath(a.converged, ROOT), "rows": rows}, f, indent=1)
    lines = ["| quantity (kPa where a load) | the seed states | local model, 0.09 m | converged default | centrifuge |",
             "|---|---|---|---|---|"]
    for r in rows:
        d = DIGITS.get(r["quantity"], 0)
        lines.append(f"| {r['quantity']} | {r['seed']} | {shown(r['local_0.09m'], d)} | {shown(r['converged'], d)} | {r['centrifuge']} |")
    with open(os.path.join(a.out, "seed_findings.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
