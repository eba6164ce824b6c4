#!/usr/bin/env python3
"""How far the Kimura footing's own answer moves under changes that should not matter, and
whether a longer time step stays inside that band (docs/mpm.md, "Quasi-static loading").

Runs the Kimura V85.6 scene on the symmetric half domain with one stress update per step (the
reference study's sweep settings), to S/B 0.3 (the window of issue 12's curve RMS), as:
  reference         cfl 0.5, the XPIC filter every 20 steps (the bundled settings);
  perturbations     cfl 0.45 and 0.55 (a time step 10 % shorter or longer), each with the filter
                    every 20 steps and with the filter's interval held in time (22 and 18 steps);
                    K0 0.40001 instead of 0.4 (the initial stresses moved by 2.5e-5);
  candidates        cfl 0.7 (30 % fewer steps), with the filter every 20 steps and every 14 (its
                    interval held in time: 20 x 0.5 / 0.7);
  filter            the XPIC filter every 500 steps instead of 20, on V85.6 and on H86.7 (whose
                    reference is its own scene with the bundled settings).
The time step is set by the few particles under the footing (their wave speed is 1.6-1.8 times
that of the bulk), so cfl is the only handle on the number of steps that leaves the soil's mass
as it is. Writes:
  OUT/time_step.csv: per case q_ult and its settlement, the first peak, the load at S/B 0.05,
    0.2 and 0.3, the RMS difference from its test's reference over S/B 0-0.09 (before the peak),
    0-0.15 and 0-0.3 (in % of the reference's q_ult), steps and wall time;
  OUT/time_step.png: the curves beside Kimura et al.'s (1985), one panel per test.
A case whose summary.json exists is reused, so the study resumes; cases can be spread over
processes with --only.

  python3 studies/footing_time_step.py [--out DIR] [--threads N] [--only NAME,...] [--tool PATH]
"""
import os
import sys

from footing_common import add_rms_to_reference, plot_beside_kimura, study_arguments, value_at, write_table
from footing_loading_rate import run_case
from footing_loading_rate import scene_for as loading_rate_scene

STOP_S_OVER_B = 0.3
# (name, role, cfl, XPIC interval in steps, K0, test)
CASES = [("reference", "reference", 0.5, 20, 0.4, "V85.6"),
         ("cfl_0.45", "perturbation", 0.45, 20, 0.4, "V85.6"),
         ("cfl_0.55", "perturbation", 0.55, 20, 0.4, "V85.6"),
         ("cfl_0.45_xpic_22", "perturbation", 0.45, 22, 0.4, "V85.6"),
         ("cfl_0.55_xpic_18", "perturbation", 0.55, 18, 0.4, "V85.6"),
         ("K0_0.40001", "perturbation", 0.5, 20, 0.40001, "V85.6"),
         ("cfl_0.7", "candidate", 0.7, 20, 0.4, "V85.6"),
         ("cfl_0.7_xpic_14", "candidate", 0.7, 14, 0.4, "V85.6"),
         ("xpic_500", "filter", 0.5, 500, 0.4, "V85.6"),
         ("H86.7_reference", "reference", 0.5, 20, 0.4, "H86.7"),
         ("H86.7_xpic_500", "filter", 0.5, 500, 0.4, "H86.7")]
TESTS = ("V85.6", "H86.7")
MARKS = (0.05, 0.2, 0.3)
RMS_WINDOWS = (0.09, 0.15, 0.3)


def scene_for(name, cfl, xpic_every, K0, test):
    """The loading-rate study's scene of TEST at the study's speed, with this case's changes."""
    s = loading_rate_scene(test, 1, 1, cfl)
    s["name"] = name
    s["solver"]["xpic_every"] = xpic_every
    s["initial_stress"]["K0"] = K0
    s["stop"]["S_over_B"] = STOP_S_OVER_B
    return s


def main():
    a = study_arguments(__doc__, "footing_time_step", "comma-separated case names to run (e.g. cfl_0.45); default: all")
    os.makedirs(a.out, exist_ok=True)
    table = []
    for name, role, cfl, xpic_every, K0, test in CASES:
        row = run_case(a, name, lambda: scene_for(name, cfl, xpic_every, K0, test))
        if row is None:
            continue
        S, q = row["curve"]
        row.update({"test": test, "role": role, "cfl": cfl, "xpic_every": xpic_every, "K0": K0})
        for m in MARKS:
            row[f"q_at_{m}_kPa"] = round(value_at(S, q, m), 1)
        table.append(row)
    def reference_of(r):
        return next((x for x in table if x["role"] == "reference" and x["test"] == r["test"]), None)

    add_rms_to_reference(table, reference_of, RMS_WINDOWS)
    for r in table:
        ref = reference_of(r)
        r["q_max_change_pct"] = "" if ref is None else round(100.0 * (r["q_max_kPa"] / ref["q_max_kPa"] - 1.0), 2)
        print(f"{r['case']:18s} {r['role']:12s} q_ult {r['q_max_kPa']:.1f} kPa at S/B {r['S_at_max_over_B']} "
              f"({r['q_max_change_pct']} %); RMS to S/B {', '.join(str(u) for u in RMS_WINDOWS)}: "
              f"{', '.join(str(r[f'rms_to_{u}_pct']) for u in RMS_WINDOWS)} %; {r['steps']} steps, {r['wall_s']:.0f} s")
    fields = ["case", "test", "role", "cfl", "xpic_every", "K0", "q_max_kPa", "S_at_max_over_B", "q_max_change_pct",
              "q_first_peak_kPa", "S_first_peak_over_B"] + [f"q_at_{m}_kPa" for m in MARKS] + \
             [f"rms_to_{u}_pct" for u in RMS_WINDOWS] + ["max_kinetic_ratio", "steps", "wall_s", "threads"]
    write_table(os.path.join(a.out, "time_step.csv"), fields, table)
    plot_beside_kimura(os.path.join(a.out, "time_step.png"),
                       {test: (f"Kimura {test}, cell 0.09 m, half domain: time step and filter",
                               [(r["record"], r["case"]) for r in table if r["test"] == test]) for test in TESTS},
                       STOP_S_OVER_B,
                       key="top right")
    print(f"wrote {os.path.join(a.out, 'time_step.csv')} and time_step.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
