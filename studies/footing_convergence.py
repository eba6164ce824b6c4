#!/usr/bin/env python3
"""Cell-size convergence study of the Kimura footings (docs/footing-study.md, "The Kimura footings with the
contact footing", "Cell size"; results in bench/results/footing_convergence/).

Runs each scene with acst_mpm (skipping those whose summary.json already exists, so the study
can be resumed), then writes OUT/convergence.csv (q_ult and S_ult/B, the first peak, the peak of
q averaged over S/B +- 0.005, the load at S/B 0.5, steps and wall time per run) and one overlay
figure per lab test (OUT/<test>_curves.png) with the Kimura data.

  python3 studies/footing_convergence.py [--out DIR] [--threads N] [--only NAME,NAME...] [--follow-footing]

--follow-footing runs each scene with grid/follow_footing true (docs/mpm.md, "The grid follows the
footing"), from a copy written to OUT/scenes/.
"""
import csv
import json
import os
import subprocess
import sys

from footing_common import ROOT, gp_quoted, read_curve, scene_with_absolute_paths, study_arguments, value_at

SCENES = os.path.join(ROOT, "data", "scenes", "mpm")
# (test, cell size label, scene file), coarse to fine. The scenes differ in the cell size (and
# the particles per cell) only: half domain, one stress update per step, the delivered set.
CASES = []
for test, base in (("V85.6", "kimura_V85.6_alpha0"), ("H86.7", "kimura_H86.7_alpha90")):
    for label, tag in (("0.18", "h018"), ("0.09", "h009"), ("0.09 (2x2 ppc, averaged)", "h009ppc2"), ("0.06", "h006"), ("0.045", "h0045")):
        CASES.append((test, label, os.path.join(SCENES, "convergence", f"{base}_{tag}.json")))


def highest_window_mean(S, q, half_width=0.005):
    """The highest mean of q over a window of S/B +- half_width: a peak that one noisy row (a
    contact spike, frequent at 2 x 2 particles per cell) cannot make."""
    best, lo, hi, total = 0.0, 0, 0, 0.0
    for i in range(len(S)):
        while hi < len(S) and S[hi] <= S[i] + half_width:
            total += q[hi]
            hi += 1
        while S[lo] < S[i] - half_width:
            total -= q[lo]
            lo += 1
        best = max(best, total / (hi - lo))
    return best


def with_rows_following(scene, out):
    """A copy of the scene in OUT/scenes/ with grid/follow_footing true and its files' paths
    made absolute (they are relative to the scene's folder)."""
    s = scene_with_absolute_paths(scene)
    s["grid"]["follow_footing"] = True
    os.makedirs(os.path.join(out, "scenes"), exist_ok=True)
    copy = os.path.join(out, "scenes", os.path.basename(scene))
    with open(copy, "w") as f:
        json.dump(s, f, indent=1)
    return copy


def main():
    a = study_arguments(__doc__, "footing_convergence", "comma-separated scene names (file stems) to run; default: all",
                        [("--follow-footing", "run every scene with grid/follow_footing true")])
    os.makedirs(a.out, exist_ok=True)
    table = []
    for test, label, scene in CASES:
        stem = os.path.splitext(os.path.basename(scene))[0]
        run_dir = os.path.join(a.out, stem)
        summary = os.path.join(run_dir, "summary.json")
        wanted = not a.only or stem in a.only.split(",")
        failed = os.path.join(run_dir, "load_settlement.failed.csv")
        if wanted and not os.path.exists(summary):
            print(f"== {stem} (cell {label})", flush=True)
            run_scene = with_rows_following(scene, a.out) if a.follow_footing else scene
            done = subprocess.run([a.tool, "--threads", str(a.threads), "--output", run_dir, run_scene])
            if done.returncode not in (0, 1):  # 1: the simulation failed; it leaves its record
                return done.returncode
        if os.path.exists(summary):
            with open(summary) as f:
                s = json.load(f)
            S, q = read_curve(os.path.join(run_dir, "load_settlement.csv"))
            first = s["q_first_peak_kPa"]
            row = {"q_ult_kPa": round(s["q_ult_kPa"], 1), "S_ult_over_B": round(s["S_ult_over_B"], 4),
                   "q_first_peak_kPa": "" if first is None else round(first, 1),
                   "S_first_peak_over_B": "" if first is None else round(s["S_first_peak_over_B"], 4),
                   "peak_reached": s["peak_reached"], "particles": s["particles"], "steps": s["steps"],
                   "wall_s": round(s["wall_s"], 1), "threads": s["threads"], "failed_at_S_over_B": "",
                   "csv": os.path.relpath(os.path.join(run_dir, "load_settlement.csv"), a.out)}
        elif os.path.exists(failed):  # the record up to the failure: the peak if it was passed
            S, q = read_curve(failed)
            # the last 0.01 B before a failure are the blow-up, not the soil
            k = max((i for i in range(len(q)) if S[i] <= S[-1] - 0.01), key=lambda i: q[i])
            row = {"q_ult_kPa": round(q[k], 1), "S_ult_over_B": round(S[k], 4), "q_first_peak_kPa": "", "S_first_peak_over_B": "",
                   "peak_reached": q[-1] < 0.95 * q[k],
                   "particles": "", "steps": "", "wall_s": "", "threads": a.threads, "failed_at_S_over_B": round(S[-1], 4),
                   "csv": os.path.relpath(failed, a.out)}
        else:
            continue
        row = {"test": test, "cell": label, "scene": stem, **row, "q_ult_mean_0.01B_kPa": round(highest_window_mean(S, q), 1),
               "q_at_SB_0.5_kPa": round(value_at(S, q, 0.5), 1)}
        table.append(row)
    with open(os.path.join(a.out, "convergence.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0].keys()) if table else ["test"])
        w.writeheader()
        w.writerows(table)
    variant = ", rows following the footing" if a.follow_footing else ""
    for test in ("V85.6", "H86.7"):
        rows = [r for r in table if r["test"] == test]
        if not rows:
            continue
        lab = os.path.join(ROOT, "data", "lab", "kimura_1985", test + ".csv")
        png = os.path.join(a.out, test + "_curves.png")
        plots = [f"{gp_quoted(os.path.join(a.out, r['csv']))} using 'S_over_B':'q_kPa' with lines lw 2 title "
                 + gp_quoted(f"MPM, cell {r['cell']} m" + (f" (failed at S/B {r['failed_at_S_over_B']})" if r["failed_at_S_over_B"] != "" else ""))
                 for r in rows]
        plots.append(f"{gp_quoted(lab)} using 'S_over_B':'q_kPa' with points pt 7 ps 0.5 lc rgb 'black' title "
                     + gp_quoted(f"Kimura et al. (1985) {test}"))
        script = ("set terminal pngcairo size 1000,700 noenhanced\nset datafile separator ','\nset datafile commentschars '#'\n"
                  f"set output {gp_quoted(png)}\nset key top right\nset xlabel 'S/B'\nset ylabel 'q = V/B [kPa]'\n"
                  f"set title 'Kimura {test}: contact footing, cell-size convergence{variant}'\nset xrange [0:0.5]\nset yrange [0:*]\n"
                  "plot " + ", ".join(plots) + "\n")
        subprocess.run(["gnuplot"], input=script, text=True, check=False)
    print(f"wrote {os.path.join(a.out, 'convergence.csv')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
