#!/usr/bin/env python3
"""The decision rule's runs (docs/calibration.md, "Choosing the delivered set: the decision rule"):
every candidate of data/calibration/decision/ fitted without each fold of folds.json and the fold
predicted, by acst_fit --cross-validate on a description made of the candidate's experiments that
touch none of the fold's files plus the fold's experiments. Each (candidate, fold) pair keeps its
result in OUT/runs/CANDIDATE/FOLD/result.json the moment it ends, so the study goes on from where
it stopped (--budget MINUTES ends it between pairs); --summary (or the last pair) writes
OUT/decision.json, OUT/decision.md and OUT/decision.png: each fold's predicted error E_k, the score
S (their mean) with its bootstrap interval over the folds, the paired difference from `delivered`
and the decision the rule gives. Results in bench/results/set_decision/."""
import copy
import glob
import json
import os
import random
import subprocess
import sys
import tempfile
import time

from calibration_runs import TABLE1, peak_line, peak_rows
from footing_common import ROOT, gp_quoted, tool_arguments, write_table

DECISION = os.path.join(ROOT, "data", "calibration", "decision")
CANDIDATES = ["delivered", "mc_free", "table1", "mc_free_table1", "closing", "mc_free_table1_closing"]
ALL = "mc_free_table1_closing"  # the candidate that holds every experiment (folds.json)
RESAMPLES, SEED = 10000, 1


def experiment_id(e):
    return e.get("id") or os.path.splitext(os.path.basename(e["data"]))[0]


def files_of(e):
    return set(e["data"] if isinstance(e["data"], list) else [e["data"]])


def absolute(description_path):
    """The description as a dict, its data files absolute (they are relative to its folder)."""
    with open(description_path) as f:
        d = json.load(f)
    here = os.path.dirname(description_path)
    for e in d["experiments"]:
        e["data"] = ([os.path.normpath(os.path.join(here, p)) for p in e["data"]] if isinstance(e["data"], list)
                     else os.path.normpath(os.path.join(here, e["data"])))
    return d


def pair_description(candidate, fold, held_ids, registry):
    """The candidate without every experiment that uses a held-out file, plus the fold's experiments."""
    d = copy.deepcopy(candidate)
    held = [registry[i] for i in held_ids]
    held_files = set().union(*(files_of(e) for e in held))
    d["experiments"] = [e for e in d["experiments"] if not (files_of(e) & held_files)] + copy.deepcopy(held)
    kept_types = {e.get("test", "") for e in d["experiments"]}
    for t in {e.get("test", "") for e in candidate["experiments"]} - kept_types - {""}:
        del d["weights"]["types"][t]  # its experiments went with the fold's files (a closing of held-out curves)
    types = {e.get("test", "") for e in held}
    for t in types - set(d["weights"]["types"]) - {""}:
        d["weights"]["types"][t] = 0.2  # only predicted: the type weight never enters a fit
    d["cross_validation"] = {"folds": {fold: held_ids}}
    d["name"] = d["name"] + "_" + fold
    return d


def run_pair(a, name, fold, candidate, held_ids, registry):
    """Runs one (candidate, fold) pair unless its result is kept; returns the result."""
    folder = os.path.join(a.out, "runs", name, fold)
    done = os.path.join(folder, "result.json")
    if os.path.exists(done):
        with open(done) as f:
            return json.load(f)
    os.makedirs(folder, exist_ok=True)
    d = pair_description(candidate, fold, held_ids, registry)
    path = os.path.join(folder, "description.json")
    with open(path, "w") as f:
        json.dump(d, f, indent=1)
    t0 = time.time()
    out = os.path.join(folder, "cv")
    run = subprocess.run([a.tool, "--cross-validate", "--quiet", "--no-plot", "--threads", str(a.threads), "--output",
                          out, path], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"{name} / {fold}: acst_fit failed: {run.stderr.strip()}")
    with open(os.path.join(out, d["name"] + "_cv_report.json")) as f:
        report = json.load(f)
    entry = next(x for x in report["folds"] if x["name"] == fold)
    result = {"candidate": name, "fold": fold, "predicted": entry["predicted_rms_normalised"],
              "fitted": entry["fitted_rms_normalised"], "wall_s": round(time.time() - t0, 1),
              "values_without_fold": entry.get("values", {})}
    tmp = done + ".partial"
    with open(tmp, "w") as f:
        json.dump(result, f, indent=1)
    os.replace(tmp, done)
    return result


def table1_beside(a, candidate):
    """Reported beside the score, not deciding: Fukushima & Tatsuoka's 78 Table 1 peaks predicted
    with the set the candidate fitted without `source_ft84` (the fold that holds them out): the mean
    error, the mean absolute error, the mean error at sigma3' >= 9 kPa, and the fall of phi with
    e_0.3 at fixed pressure (b of phi = a + b e_0.3 + c ln sigma3') simulated and measured. Kept in
    runs/CANDIDATE/source_ft84/table1.json."""
    folder = os.path.join(a.out, "runs", candidate, "source_ft84")
    kept = os.path.join(folder, "table1.json")
    if os.path.exists(kept):
        with open(kept) as f:
            return json.load(f)
    parameters = glob.glob(os.path.join(folder, "cv", "*_cv_source_ft84_parameters.json"))
    if len(parameters) != 1:
        sys.exit(f"{candidate} / source_ft84: expected one set fitted without the fold in {folder}/cv")
    with tempfile.TemporaryDirectory() as scratch:
        rows = peak_rows(os.path.join(scratch, "table1"), TABLE1, parameters[0], {}, a.tool, f"{candidate} / Table 1")
    mean = lambda v: sum(v) / len(v)
    high = [r for r in rows if r[0] >= 9.0]
    result = {"candidate": candidate, "parameters": os.path.relpath(parameters[0], a.out), "rows": len(rows),
              "bias_deg": mean([r[3] - r[2] for r in rows]), "mean_abs_deg": mean([abs(r[3] - r[2]) for r in rows]),
              "bias_deg_sigma3_ge_9": mean([r[3] - r[2] for r in high])}
    for tag, chosen in (("", rows), ("_sigma3_ge_9", high)):
        for source, column in (("simulated", 3), ("measured", 2)):
            result[f"dphi_de_{source}_deg{tag}"] = peak_line(chosen, column)[0][1]
    with open(kept + ".partial", "w") as f:
        json.dump(result, f, indent=1)
    os.replace(kept + ".partial", kept)
    return result


def percentile(values, q):
    v = sorted(values)
    k = (len(v) - 1) * q
    lo, hi = int(k), min(int(k) + 1, len(v) - 1)
    return v[lo] + (v[hi] - v[lo]) * (k - lo)


def summarise(a, folds, results):
    """The rule's numbers and its decision from the kept results (every pair must be there)."""
    names = list(folds)
    E = {c: [results[c][k]["predicted"] for k in names] for c in CANDIDATES}
    rng = random.Random(SEED)
    draws = [[rng.randrange(len(names)) for _ in names] for _ in range(RESAMPLES)]
    mean = lambda xs, idx: sum(xs[i] for i in idx) / len(idx)
    rows, summary = [], {}
    for c in CANDIDATES:
        S = sum(E[c]) / len(names)
        boot = [mean(E[c], idx) for idx in draws]
        diff = [mean(E[c], idx) - mean(E["delivered"], idx) for idx in draws]
        summary[c] = {"per_fold": dict(zip(names, E[c])), "score": S, "score_5_95": [percentile(boot, 0.05), percentile(boot, 0.95)],
                      "difference_from_delivered": S - sum(E["delivered"]) / len(names),
                      "difference_5_95": [percentile(diff, 0.05), percentile(diff, 0.95)]}
        rows.append([c] + [f"{x:.3f}" for x in E[c]] + [f"{S:.3f}", f"{summary[c]['score_5_95'][0]:.3f}-{summary[c]['score_5_95'][1]:.3f}",
                     f"{summary[c]['difference_from_delivered']:+.3f} ({summary[c]['difference_5_95'][0]:+.3f} to {summary[c]['difference_5_95'][1]:+.3f})"])
    best = min(CANDIDATES, key=lambda c: summary[c]["score"])
    adopt = best != "delivered" and summary[best]["difference_5_95"][1] < 0.0
    decision = {"best": best, "delivered": best if adopt else "delivered",
                "reason": (f"{best} has the lowest score and its paired difference's 95th percentile is below zero"
                           if adopt else
                           f"the lowest score is {best}'s" + ("" if best == "delivered" else
                           ", but its paired difference from delivered reaches "
                           f"{summary[best]['difference_5_95'][1]:+.3f} at the 95th percentile: not better beyond the folds' spread") +
                           "; the delivered set stays")}
    for c in CANDIDATES:
        summary[c]["table1_held_out"] = table1_beside(a, c)
    header = ["candidate"] + names + ["S", "S 5-95 %", "S - S(delivered) (5-95 %)"]
    write_table(os.path.join(a.out, "decision.csv"), header, [dict(zip(header, r)) for r in rows])
    with open(os.path.join(a.out, "decision.md"), "w") as f:
        f.write("| " + " | ".join(header) + " |\n|" + "---|" * len(header) + "\n")
        for r in rows:
            f.write("| " + " | ".join(r) + " |\n")
        f.write(f"\nDecision: {decision['reason']}.\n")
        f.write("\nReported beside the score, not deciding: Fukushima & Tatsuoka's Table 1 peaks predicted by the set "
                "each candidate fitted without `source_ft84` (the fold that holds them out; phi simulated - measured, deg; "
                "b: the fall of phi with e_0.3 at fixed pressure, deg per unit e, simulated / measured).\n\n"
                "| candidate | peaks | mean error | mean abs. error | mean error, sigma3' >= 9 kPa | b, all | b, sigma3' >= 9 kPa |\n"
                "|---|---|---|---|---|---|---|\n")
        for c in CANDIDATES:
            t = summary[c]["table1_held_out"]
            f.write(f"| {c} | {t['rows']} | {t['bias_deg']:+.2f} | {t['mean_abs_deg']:.2f} | {t['bias_deg_sigma3_ge_9']:+.2f} | "
                    + " | ".join(f"{t['dphi_de_simulated_deg' + k]:.1f} / {t['dphi_de_measured_deg' + k]:.1f} = "
                                 f"{t['dphi_de_simulated_deg' + k] / t['dphi_de_measured_deg' + k]:.2f}" for k in ("", "_sigma3_ge_9"))
                    + " |\n")
    with open(os.path.join(a.out, "decision.json"), "w") as f:
        json.dump({"folds": folds, "candidates": summary, "decision": decision, "resamples": RESAMPLES, "seed": SEED}, f, indent=1)
    plot(a, names, E)
    return decision


def plot(a, names, E):
    data = os.path.join(a.out, "decision_per_fold.dat")
    with open(data, "w") as f:
        f.write("fold " + " ".join(CANDIDATES) + "\n")
        for k, fold in enumerate(names):
            f.write(fold + " " + " ".join(f"{E[c][k]:.5f}" for c in CANDIDATES) + "\n")
    script = "\n".join([
        "set terminal pngcairo size 1100,520 noenhanced", f"set output {gp_quoted(os.path.join(a.out, 'decision.png'))}",
        "set style data histogram", "set style histogram cluster gap 1", "set style fill solid 0.8 border -1",
        "set ylabel 'predicted RMS / range of the held-out fold'", "set key top left", "set xtics rotate by -20",
        "set title 'Decision rule: each candidate fitted without the fold, the fold predicted'",
        f"plot for [c=2:{len(CANDIDATES) + 1}] {gp_quoted(data)} using c:xtic(1) title columnheader(c)"])
    subprocess.run(["gnuplot"], input=script, text=True, check=False)


def main():
    a = tool_arguments(__doc__, "set_decision", "calibration/acst_fit", [
        ("--threads", {"type": int, "default": 2}),
        ("--budget", {"type": float, "default": 0.0, "help": "minutes; no new pair starts past them (0: none)"}),
        ("--only", {"default": "", "help": "comma-separated candidates"}),
        ("--summary", {"action": "store_true", "help": "only summarise the kept results"})])
    with open(os.path.join(DECISION, "folds.json")) as f:
        folds = json.load(f)["folds"]
    candidates = {c: absolute(os.path.join(DECISION, c + ".json")) for c in CANDIDATES}
    registry = {experiment_id(e): e for e in candidates[ALL]["experiments"]}
    chosen = [c for c in CANDIDATES if not a.only or c in a.only.split(",")]
    pairs = [(c, k) for c in chosen for k in folds]
    results = {c: {} for c in CANDIDATES}
    t0, ran = time.time(), 0
    waiting = [(c, k) for c, k in pairs if not os.path.exists(os.path.join(a.out, "runs", c, k, "result.json"))]
    for n, (c, k) in enumerate([] if a.summary else waiting):
        if a.budget > 0 and time.time() - t0 > 60 * a.budget:
            print(f"budget of {a.budget:g} min spent; {len(waiting) - n} pairs wait (run again to go on)", flush=True)
            break
        r = run_pair(a, c, k, candidates[c], folds[k], registry)
        ran += 1
        left = len(waiting) - n - 1
        print(f"{c} / {k}: predicted {r['predicted']:.3f} (fitted {r['fitted']:.3f}) in {r['wall_s']:.0f} s; {left} pairs "
              f"left, about {left * (time.time() - t0) / ran / 60:.0f} min", flush=True)
    for c in CANDIDATES:  # every kept pair, also of the candidates not chosen this time
        for k in folds:
            kept = os.path.join(a.out, "runs", c, k, "result.json")
            if os.path.exists(kept):
                with open(kept) as f:
                    results[c][k] = json.load(f)
    if all(len(results[c]) == len(folds) for c in CANDIDATES):
        print(summarise(a, folds, results)["reason"])
    else:
        print("not every pair has run: no decision yet")


if __name__ == "__main__":
    main()
