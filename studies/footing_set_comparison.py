#!/usr/bin/env python3
"""The Kimura footings with the delivered parameter set, with the previous one (data/parameters:
toyoura_acst_calibrated.json, Willam & Warnke's g; toyoura_acst_li2002_calibrated.json, Li's g) and
with the delivered set without fabric evolution (k_f = 0, every other value as delivered).

Each case is the loading-rate study's reference setting (studies/footing_loading_rate.py: the
bundled scene on the half domain, one stress update per step, 0.045 m/s, cfl 0.5, to S/B 0.2)
with the set of its name. Writes:
  OUT/set_comparison.csv: per case the load at S/B 0.03, 0.06 and 0.09, the first peak, the
    largest load, the RMS difference from its reference case (the delivered set's from the
    previous one, k_f = 0's from the delivered set) over S/B 0-0.09 and 0-0.2 (over the
    reference's largest load), steps and wall time;
  OUT/set_comparison.png: the curves beside Kimura et al.'s (1985).
A case whose summary.json exists is reused; --only picks cases (one process, one case at a time).

  python3 studies/footing_set_comparison.py [--out DIR] [--threads N] [--only NAME,...] [--tool PATH]
"""
import json
import os
import sys

from footing_common import ROOT, add_rms_to_reference, plot_beside_kimura, study_arguments, write_table
from footing_loading_rate import MARKS, STOP_S_OVER_B, TESTS, run_case, scene_for

# case suffix -> (parameter file stem, values replaced in it, the suffix its RMS difference is taken from)
SETS = {"delivered": ("toyoura_acst_calibrated", {}, "li2002"), "li2002": ("toyoura_acst_li2002_calibrated", {}, None),
        "delivered_kf0": ("toyoura_acst_calibrated", {"k_f": 0.0}, "delivered")}


def set_scene(test, name, stem, replaced):
    """The loading-rate study's reference scene of TEST with the parameter set STEM, REPLACED's
    values put in (inline, so the scene says what it ran)."""
    scene = scene_for(test, 1, 1, 0.5)
    scene["name"] = name
    path = os.path.join(ROOT, "data", "parameters", stem + ".json")
    if replaced:
        with open(path) as f:
            material = json.load(f)
        material["parameters"].update(replaced)
    else:
        material = path
    scene["materials"] = {k: material for k in scene["materials"]}
    return scene


def main():
    a = study_arguments(__doc__, "footing_set_comparison", "comma-separated case names to run (e.g. V85.6_li2002); default: all")
    os.makedirs(a.out, exist_ok=True)
    table = []
    for test in TESTS:
        for key, (stem, replaced, reference) in SETS.items():
            name = f"{test}_{key}"
            row = run_case(a, name, lambda: set_scene(test, name, stem, replaced))
            if row is None:
                continue
            row.update({"test": test, "set": stem + "".join(f" {k} = {v:g}" for k, v in replaced.items()),
                        "reference": None if reference is None else f"{test}_{reference}"})
            table.append(row)
            print(f"{name:18s} q at S/B {', '.join(str(m) for m in MARKS)}: "
                  f"{', '.join('%.0f' % row[f'q_at_{m}_kPa'] for m in MARKS)} kPa; first peak {row['q_first_peak_kPa']} kPa "
                  f"at S/B {row['S_first_peak_over_B']}; largest {row['q_max_kPa']:.0f} kPa at S/B {row['S_at_max_over_B']}; "
                  f"{row['steps']} steps, {row['wall_s']:.0f} s")
    add_rms_to_reference(table, lambda r: next((x for x in table if x["case"] == r["reference"]), None), (0.09, 0.2))
    fields = ["case", "test", "set"] + [f"q_at_{m}_kPa" for m in MARKS] + \
             ["q_first_peak_kPa", "S_first_peak_over_B", "q_max_kPa", "S_at_max_over_B", "reference", "rms_to_0.09_pct", "rms_to_0.2_pct",
              "max_kinetic_ratio", "steps", "wall_s", "threads"]
    write_table(os.path.join(a.out, "set_comparison.csv"), fields, table)
    plot_beside_kimura(os.path.join(a.out, "set_comparison.png"),
                       {test: (f"Kimura {test}, cell 0.09 m, half domain, 0.045 m/s: parameter set",
                               [(r["record"], r["set"]) for r in table if r["test"] == test]) for test in TESTS}, STOP_S_OVER_B)
    print(f"wrote {os.path.join(a.out, 'set_comparison.csv')} and set_comparison.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
