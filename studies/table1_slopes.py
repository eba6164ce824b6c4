#!/usr/bin/env python3
"""Which part of the sand model sets how steeply the peak friction angle falls with the void
ratio (docs/calibration.md, "The peak friction angle against e and pressure"; results in
bench/results/table1_slopes/).

Runs the Table 1 prediction of Fukushima & Tatsuoka (1984) (data/calibration/*_table1_prediction.json:
78 drained triaxial peaks, sigma3' 1.96-392 kPa, e_0.3 0.65-0.91) with a parameter set, changed
where asked, and fits phi = a + b e_0.3 + c ln(sigma3') by least squares to the measured and to
the simulated peaks, over all rows and over pressure ranges. b is the fall with the void ratio,
c the fall with pressure, and -c/b the change of e that costs as much phi as one e-fold of
pressure: in a model whose peak depends on the state parameter psi = e - e_c(p) alone it is the
critical state line's slope de_c/dln p at the peak's pressure.

  python3 studies/table1_slopes.py [--out DIR] [--tool build/calibration/acst_fit] CASE ...
  CASE: NAME:DESCRIPTION[:key=value,...]   (DESCRIPTION a data/calibration file; the values
        replace the parameter set's, e.g. lambda_c=0.038,e_Gamma=0.9746)
Writes OUT/slopes.csv (case, rows, source, n, dphi_de_deg, dphi_dln_sigma3_deg,
equivalent_de_per_ln_sigma3, rms_deg: the fit's residual; bias_deg: the simulated minus the
measured peak, mean over the rows).
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from calibration_runs import peak_line, peak_rows  # noqa: E402
from footing_common import tool_arguments, write_table  # noqa: E402

RANGES = [("all", 0.0, 1e9), ("sigma3 >= 9 kPa", 9.0, 1e9), ("sigma3 >= 45 kPa", 45.0, 1e9), ("sigma3 < 25 kPa", 0.0, 25.0)]


def run_case(text, out, tool):
    parts = text.split(":")
    if len(parts) not in (2, 3) or not re.fullmatch(r"[A-Za-z0-9_.-]+", parts[0]):
        sys.exit(f"{text}: expected NAME:DESCRIPTION[:key=value,...] with NAME a plain stem")
    name = parts[0]
    replaced = {k: float(v) for k, v in (item.split("=", 1) for item in parts[2].split(","))} if len(parts) == 3 else {}
    return name, peak_rows(os.path.join(out, name), os.path.abspath(parts[1]), None, replaced, tool, text)


def main():
    a = tool_arguments(__doc__, "table1_slopes", "calibration/acst_fit", [("cases", {"nargs": "+"})])
    table = []
    for text in a.cases:
        name, rows = run_case(text, a.out, a.tool)
        for label, lo, hi in RANGES:
            chosen = [r for r in rows if lo <= r[0] < hi]
            for source, k in (("measured", 2), ("simulated", 3)):
                c, rms = peak_line(chosen, k)
                table.append({"case": name, "rows": label, "source": source, "n": len(chosen), "dphi_de_deg": round(c[1], 1),
                              "dphi_dln_sigma3_deg": round(c[2], 2), "equivalent_de_per_ln_sigma3": round(-c[2] / c[1], 4),
                              "rms_deg": round(rms, 2),
                              "bias_deg": round(sum(r[3] - r[2] for r in chosen) / len(chosen), 2) if k == 3 else ""})
                print(json.dumps(table[-1]), flush=True)
    write_table(os.path.join(a.out, "slopes.csv"), list(table[0]), table)


if __name__ == "__main__":
    main()
