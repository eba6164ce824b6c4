#!/usr/bin/env python3
"""Is the Kimura footing's peak converged in the loading rate? (docs/footing-study.md, "Loading rate")

Runs the Kimura V85.6 and H86.7 scenes on the symmetric half domain with one stress update per
step (the reference study's sweep settings) at the footing speed 0.045 m/s and at 1/2, 1/4 and
1/8 of it; V85.6 also at 2 and 4 times it, and at the study's speed with a time step 10 % shorter
(cfl 0.45 instead of 0.5), a change that should not matter. Each runs to S/B 0.2 (past every
peak). Writes:
  OUT/loading_rate.csv: per case the load at S/B 0.03, 0.06 and 0.09, the largest load and its
    settlement, the first peak (the first load no load within +-0.01 B exceeds), the RMS difference from its test's run at the study's settings over S/B 0-0.09
    and 0-0.2 (over that run's largest load), the largest kinetic-to-work ratio past S/B 0.02,
    steps and wall time;
  OUT/loading_rate.png: the curves of each test beside Kimura et al.'s (1985).
A case whose summary.json exists is reused, so the study resumes; cases can be spread over
processes with --only (each process one case at a time).

  python3 studies/footing_loading_rate.py [--out DIR] [--threads N] [--only NAME,...] [--tool PATH]
"""
import json
import os
import sys

from footing_common import (ROOT, add_rms_to_reference, max_kinetic_ratio, plot_beside_kimura, read_curve, run_study_case,
                            scene_with_absolute_paths, study_arguments, value_at, write_table)

SCENES = os.path.join(ROOT, "data", "scenes", "mpm")
TESTS = {"V85.6": "kimura_V85.6_alpha0_half.json", "H86.7": "kimura_H86.7_alpha90.json"}
# (test, speed factor as numerator and denominator, cfl)
CASES = [(t, 1, d, 0.5) for t in TESTS for d in (1, 2, 4, 8)] + \
        [("V85.6", f, 1, 0.5) for f in (2, 4)] + [("V85.6", 1, 1, 0.45)]
STOP_S_OVER_B = 0.2
MARKS = (0.03, 0.06, 0.09)  # settlements before the first peak, where the curves are compared
PEAK_WINDOW = 0.01  # a first peak is the largest load within +-0.01 B of itself


def first_peak(S, q):
    """The first load past S/B 0.03 that no load within +-PEAK_WINDOW B exceeds (the onset of
    softening), or None; a later, higher hump does not count."""
    for i in range(len(S)):
        if S[i] < 0.03 or S[i] + PEAK_WINDOW > S[-1]:
            continue
        if all(q[j] <= q[i] for j in range(len(S)) if abs(S[j] - S[i]) <= PEAK_WINDOW):
            return i
    return None


def case_name(test, num, den, cfl):
    return f"{test}_speed_{num}_{den}" + ("" if cfl == 0.5 else f"_cfl_{cfl}")


def scene_for(test, num, den, cfl):
    """The bundled scene on the half domain, one stress update per step, speed x num / den."""
    s = scene_with_absolute_paths(os.path.join(SCENES, TESTS[test]))
    s["name"] = case_name(test, num, den, cfl)
    s["output"] = {"lab_curve": s["output"]["lab_curve"], "lab_label": s["output"]["lab_label"],
                   "vtk_every_S_over_B": 1.0, "checkpoint_every_s": 0}
    s["footing"]["symmetric_half"] = True
    s["footing"]["speed"] *= num / den
    s["solver"]["cfl"] = cfl
    s["solver"]["stress_update"] = "first"
    s["stop"]["S_over_B"] = STOP_S_OVER_B
    return s


def run_case(a, name, make_scene):
    """Runs case NAME (its scene from make_scene()) into OUT/NAME unless --only leaves it out or
    its summary.json exists; returns its row (loads at MARKS, first peak, largest load, kinetic
    ratio, steps, wall time, the record and its curve) or None if it has no summary."""
    run_dir = run_study_case(a, name, make_scene)
    summary = os.path.join(run_dir, "summary.json")
    if not os.path.exists(summary):
        return None
    with open(summary) as f:
        s = json.load(f)
    record = os.path.join(run_dir, "load_settlement.csv")
    S, q = read_curve(record)
    k = max(range(len(S)), key=lambda i: q[i])
    f1 = first_peak(S, q)
    row = {"case": name, "q_max_kPa": round(q[k], 1), "S_at_max_over_B": round(S[k], 4),
           "q_first_peak_kPa": "" if f1 is None else round(q[f1], 1), "S_first_peak_over_B": "" if f1 is None else round(S[f1], 4),
           "max_kinetic_ratio": float("%.3g" % max_kinetic_ratio(record)),
           "steps": s["steps"], "wall_s": round(s["wall_s"], 1), "threads": s["threads"], "record": record, "curve": (S, q)}
    for m in MARKS:
        row[f"q_at_{m}_kPa"] = round(value_at(S, q, m), 1)
    return row


def main():
    a = study_arguments(__doc__, "footing_loading_rate", "comma-separated case names to run (e.g. V85.6_speed_1_2); default: all")
    os.makedirs(a.out, exist_ok=True)
    table = []
    for test, num, den, cfl in CASES:
        name = case_name(test, num, den, cfl)
        row = run_case(a, name, lambda: scene_for(test, num, den, cfl))
        if row is None:
            continue
        row.update({"test": test, "speed_m_per_s": round(0.045 * num / den, 6), "cfl": cfl})
        table.append(row)
        print(f"{name:26s} q at S/B {', '.join(str(m) for m in MARKS)}: "
              f"{', '.join('%.0f' % row[f'q_at_{m}_kPa'] for m in MARKS)} kPa; largest {row['q_max_kPa']:.0f} kPa at S/B {row['S_at_max_over_B']}; "
              f"first peak {row['q_first_peak_kPa']} kPa at S/B {row['S_first_peak_over_B']}; "
              f"K/W {row['max_kinetic_ratio']:.1e}; {row['steps']} steps, {row['wall_s']:.0f} s")
    # Each curve against its test's run at the study's settings: RMS of the difference over S/B
    # 0.005-0.09 (before any curve's first peak) and over 0.005-0.2, over that run's largest load.
    add_rms_to_reference(table, lambda r: next((x for x in table if x["case"] == case_name(r["test"], 1, 1, 0.5)), None),
                         (0.09, 0.2))
    for r in table:
        print(f"{r['case']:26s} RMS against {r['test']} at 0.045 m/s, cfl 0.5: {r['rms_to_0.09_pct']} % to S/B 0.09, "
              f"{r['rms_to_0.2_pct']} % to 0.2")
    fields = ["case", "test", "speed_m_per_s", "cfl"] + [f"q_at_{m}_kPa" for m in MARKS] + \
             ["q_max_kPa", "S_at_max_over_B", "q_first_peak_kPa", "S_first_peak_over_B", "rms_to_0.09_pct", "rms_to_0.2_pct", "max_kinetic_ratio", "steps", "wall_s", "threads"]
    write_table(os.path.join(a.out, "loading_rate.csv"), fields, table)
    plot_beside_kimura(os.path.join(a.out, "loading_rate.png"),
                       {test: (f"Kimura {test}, cell 0.09 m, half domain: footing speed",
                               [(r["record"], "%g m/s, cfl %g" % (r["speed_m_per_s"], r["cfl"])) for r in table if r["test"] == test])
                        for test in TESTS}, STOP_S_OVER_B)
    print(f"wrote {os.path.join(a.out, 'loading_rate.csv')} and loading_rate.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
