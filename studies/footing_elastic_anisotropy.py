#!/usr/bin/env python3
"""The Kimura footings with the fabric-dependent elasticity of docs/model.md section 2 (the option
elastic_anisotropy a: Young's modulus along the fabric's major axis exp(a |F|) times across it).

Each case is the loading-rate study's reference setting (studies/footing_loading_rate.py: the
bundled scene on the half domain, one stress update per step, 0.045 m/s, cfl 0.5, to S/B 0.2)
with the delivered set (data/parameters/toyoura_acst_calibrated.json) and the a of its name;
a = 0 is the delivered set itself. For V85.6 (bedding 0) a > 0 stiffens the vertical, for H86.7
(bedding 90) it softens it. Writes:
  OUT/materials/: the parameter files (the delivered set with elastic_anisotropy a);
  OUT/elastic_anisotropy.csv: per case the secants q/(S/B) at q = 250, 500 and 1000 kPa (as
    studies/footing_initial_slope.py), the load at S/B 0.03, 0.06 and 0.09, the first peak, the
    largest load, the RMS difference from a = 0 over S/B 0-0.09 and 0-0.2 (over a = 0's largest
    load), steps and wall time; Kimura et al.'s (1985) secants in rows of their own;
  OUT/elastic_anisotropy.png: the curves beside Kimura's.
A case whose summary.json exists is reused; --only picks cases (one process, one case at a time).

  python3 studies/footing_elastic_anisotropy.py [--out DIR] [--threads N] [--only NAME,...] [--tool PATH]
"""
import json
import os
import sys

from footing_common import ROOT, plot_beside_kimura, read_curve, rms_difference_pct, study_arguments, write_table
from footing_initial_slope import LEVELS, first_reach
from footing_loading_rate import MARKS, STOP_S_OVER_B, TESTS, run_case, scene_for

ANISOTROPY = (0.0, 1.0, 2.0)
DELIVERED = os.path.join(ROOT, "data", "parameters", "toyoura_acst_calibrated.json")


def case_name(test, a):
    return f"{test}_a{a:g}"


def material_file(out, a):
    """The delivered set with elastic_anisotropy a, written under OUT/materials (a = 0: the set's own file)."""
    if a == 0.0:
        return DELIVERED
    with open(DELIVERED) as f:
        material = json.load(f)
    material["parameters"]["elastic_anisotropy"] = a
    path = os.path.abspath(os.path.join(out, "materials", f"toyoura_acst_calibrated_a{a:g}.json"))
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        json.dump(material, f, indent=2, sort_keys=True)
    return path


def anisotropy_scene(test, name, path):
    scene = scene_for(test, 1, 1, 0.5)
    scene["name"] = name
    scene["materials"] = {k: path for k in scene["materials"]}
    return scene


def secants(curve):
    S, q = curve
    return {f"secant_{lv:g}_kPa": round(lv / s) if s > 0 else "" for lv in LEVELS for s in [first_reach(S, q, lv)]}


def main():
    a = study_arguments(__doc__, "footing_elastic_anisotropy", "comma-separated case names to run (e.g. V85.6_a2); default: all")
    os.makedirs(a.out, exist_ok=True)
    table = []
    for test in TESTS:
        kimura = read_curve(os.path.join(ROOT, "data", "lab", "kimura_1985", test + ".csv"))
        table.append({"case": f"{test}_Kimura", "test": test, "elastic_anisotropy": "", **secants(kimura)})
        for an in ANISOTROPY:
            name = case_name(test, an)
            row = run_case(a, name, lambda: anisotropy_scene(test, name, material_file(a.out, an)))
            if row is None:
                continue
            row.update({"test": test, "elastic_anisotropy": an, **secants(row["curve"])})
            table.append(row)
            print(f"{name:12s} secants at q {', '.join('%g' % lv for lv in LEVELS)} kPa: "
                  f"{', '.join(str(row[f'secant_{lv:g}_kPa']) for lv in LEVELS)} kPa; q at S/B {', '.join(str(m) for m in MARKS)}: "
                  f"{', '.join('%.0f' % row[f'q_at_{m}_kPa'] for m in MARKS)} kPa; first peak {row['q_first_peak_kPa']} kPa "
                  f"at S/B {row['S_first_peak_over_B']}; {row['steps']} steps, {row['wall_s']:.0f} s")
    for r in table:
        ref = next((x for x in table if x["case"] == case_name(r["test"], 0.0)), None)
        for upto in (0.09, 0.2):
            r[f"rms_to_{upto}_pct"] = "" if ref is None or ref is r or "curve" not in r else \
                rms_difference_pct(r["curve"], ref["curve"], upto, ref["q_max_kPa"])
    fields = ["case", "test", "elastic_anisotropy"] + [f"secant_{lv:g}_kPa" for lv in LEVELS] + \
             [f"q_at_{m}_kPa" for m in MARKS] + \
             ["q_first_peak_kPa", "S_first_peak_over_B", "q_max_kPa", "S_at_max_over_B", "rms_to_0.09_pct", "rms_to_0.2_pct",
              "max_kinetic_ratio", "steps", "wall_s", "threads"]
    write_table(os.path.join(a.out, "elastic_anisotropy.csv"), fields, table)
    plot_beside_kimura(os.path.join(a.out, "elastic_anisotropy.png"),
                       {test: (f"Kimura {test}, cell 0.09 m, half domain, 0.045 m/s: elastic_anisotropy a",
                               [(r["record"], f"a = {r['elastic_anisotropy']:g}") for r in table
                                if r["test"] == test and "record" in r]) for test in TESTS}, STOP_S_OVER_B)
    print(f"wrote {os.path.join(a.out, 'elastic_anisotropy.csv')} and elastic_anisotropy.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
