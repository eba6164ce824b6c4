"""Helpers for the studies that run acst_fit predictions with a changed parameter set
(table1_slopes.py, lt88_fabric_closing.py)."""
import csv
import json
import os
import subprocess
import sys


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
