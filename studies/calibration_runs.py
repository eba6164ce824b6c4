"""Helpers for the studies that run acst_fit predictions with a changed parameter set
(table1_slopes.py, lt88_fabric_closing.py, kf_profile.py, set_decision.py)."""
import csv
import glob
import json
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TABLE1 = os.path.join(ROOT, "data", "calibration", "toyoura_acst_table1_prediction.json")


def run_prediction(case_dir, description, parameter_set, replaced, tool, label):
    """Writes CASE_DIR/parameters.json (the set's parameters with `replaced` put in; every key
    must be one of them) and CASE_DIR/description.json (`description`, a dict with absolute data
    paths, pointed at that set and at CASE_DIR/report), runs acst_fit on it and returns the
    report's folder; a failure exits naming `label`."""
    os.makedirs(case_dir, exist_ok=True)
    with open(parameter_set) as f:
        p = json.load(f)
    for key, value in replaced.items():
        if key not in p["parameters"]:
            sys.exit(f"{label}: '{key}' is not a parameter of {parameter_set}")
        p["parameters"][key] = value
    material = os.path.join(case_dir, "parameters.json")
    with open(material, "w") as f:
        json.dump(p, f, indent=1)
    d = dict(description, material={"file": material}, output={"directory": os.path.join(case_dir, "report")})
    path = os.path.join(case_dir, "description.json")
    with open(path, "w") as f:
        json.dump(d, f, indent=1)
    run = subprocess.run([tool, path], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"{label}: acst_fit failed: {run.stderr.strip()}")
    return d["output"]["directory"]


def points(report, experiment):
    """The rows of an experiment's curves/EXPERIMENT_points.csv in a report's folder."""
    with open(os.path.join(report, "curves", experiment + "_points.csv")) as f:
        return list(csv.DictReader(f))


def peak_rows(case_dir, description_path, parameter_set, replaced, tool, label):
    """Runs a peak prediction (a description like TABLE1, its data paths taken relative to it)
    with `parameter_set` (None: the description's own) and returns its rows as
    (sigma3' kPa, e_0.3, measured phi, simulated phi)."""
    with open(description_path) as f:
        d = json.load(f)
    here = os.path.dirname(os.path.abspath(description_path))
    d["defaults"]["data"] = os.path.normpath(os.path.join(here, d["defaults"]["data"]))
    d["name"] = os.path.basename(case_dir)
    material = parameter_set or os.path.normpath(os.path.join(here, d["material"]["file"]))
    report = run_prediction(case_dir, d, material, replaced, tool, label)
    rows = []
    for path in sorted(glob.glob(os.path.join(report, "curves", "*_points.csv"))):
        with open(path) as f:
            rows += [(float(r["sigma3_kPa"]), float(r["void_ratio"]), float(r["measured"]), float(r["simulated"]))
                     for r in csv.DictReader(f)]
    return rows


def least_squares(X, y):
    """Coefficients of y ~ X (rows of 3) from the normal equations, by Gauss-Jordan elimination."""
    A = [[sum(x[i] * x[j] for x in X) for j in range(3)] + [sum(x[i] * v for x, v in zip(X, y))] for i in range(3)]
    for i in range(3):
        k = max(range(i, 3), key=lambda r: abs(A[r][i]))
        A[i], A[k] = A[k], A[i]
        for r in range(3):
            if r != i:
                f = A[r][i] / A[i][i]
                A[r] = [a - f * b for a, b in zip(A[r], A[i])]
    return [A[i][3] / A[i][i] for i in range(3)]


def peak_line(rows, column):
    """phi = a + b e_0.3 + c ln(sigma3') fitted to one column of peak_rows (2 measured,
    3 simulated): (a, b, c) and the fit's RMS residual."""
    X = [(1.0, r[1], math.log(r[0])) for r in rows]
    y = [r[column] for r in rows]
    c = least_squares(X, y)
    rms = math.sqrt(sum((v - (c[0] + c[1] * x[1] + c[2] * x[2])) ** 2 for x, v in zip(X, y)) / len(y))
    return c, rms
