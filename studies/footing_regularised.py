#!/usr/bin/env python3
"""The Kimura footings (V85.6 and H86.7 first) with the regularised sand (docs/footing-study.md, "The
regularised footing"; results in bench/results/footing_regularised/).

Each case is the half-domain convergence scene of its test (data/scenes/mpm/convergence/, one
stress update per step, the delivered set) at a cell size, with the regularisation at its
default internal length (from Toyoura's grains at Kimura's 30 g) or the local model, at a
loading speed (a factor of the study's 0.045 m/s) and a CFL number. A case whose summary.json
exists is not run again (the study resumes). Writes OUT/convergence.csv (one row per run:
case, cell_m, internal_length_m, speed_factor, cfl, q_ult_kPa, S_ult_over_B, wall_s, and the
first peak, q at S/B 0.1 and 0.25), OUT/<test>_curves.png (the runs over the centrifuge curve)
and OUT/q_ult_against_h.png.

  python3 studies/footing_regularised.py [--out DIR] [--threads 2] [--stop 0.25] CASE ...
  CASE: TEST,h=0.045[,l=default|0|METRES][,speed=1][,cfl=0.5][,grid=uniform|graded][,largest=METRES]
        [,window=B][,set=acst|isotropic|FILE.json][,m=1][,lc=METRES][,kc=0.5]   (TEST: one of the reference study's
        kimura group, V85.6, V75.1, V64.6, H86.7, H76.5, H61.0; largest: the graded grid's largest cell, default 4 h;
        window: its window's half-width and depth in footing widths, default 3;
        set: the delivered ACST set, the delivered isotropic one (data/parameters/toyoura_isotropic_calibrated.json),
        or a material file relative to the repository, whose plain stem joins the case's name;
        m: the regularisation's over-nonlocal factor; lc, kc: micropolar rotations' length and modulus
        ratio, docs/mpm.md "Micropolar rotations")
"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys

from footing_common import ROOT, gp_quoted, old_rows, read_curve, run_case, scene_with_absolute_paths, write_table

SCENES = os.path.join(ROOT, "data", "scenes", "mpm", "convergence")
BASE = {"V85.6": "kimura_V85.6_alpha0_h0045.json", "H86.7": "kimura_H86.7_alpha90_h0045.json"}
SWEEP = os.path.join(ROOT, "data", "sweeps", "reference_study.json")
BODY_KEYS = ("density", "relative_density_pct", "bedding_angle_deg")


def kimura_tests():
    """The reference study's kimura group, {test: its sand's density, relative density and bedding}, as
    the sweep (data/sweeps/reference_study.json) defines them: the one place the six tests are named."""
    with open(SWEEP) as f:
        cases = json.load(f)["cases"]
    return {c["name"]: {k: c["set"]["/bodies/0/" + k] for k in BODY_KEYS} for c in cases if "kimura" in c.get("group", [])}


KIMURA_TESTS = kimura_tests()
SETS = {"acst": None, "isotropic": os.path.join(ROOT, "data", "parameters", "toyoura_isotropic_calibrated.json")}
FIELDS = ["case", "grid", "set", "cell_m", "internal_length_m", "speed_factor", "cfl", "q_ult_kPa", "S_ult_over_B", "wall_s",
          "q_first_peak_kPa", "S_first_peak_over_B", "q_at_SB0.1_kPa", "q_at_SB0.25_kPa", "final_S_over_B",
          "max_kinetic_ratio", "status"]


def parse_case(text):
    parts = text.split(",")
    if parts[0] not in KIMURA_TESTS:
        sys.exit(f"{text}: TEST is one of {', '.join(KIMURA_TESTS)}")
    c = {"test": parts[0], "h": None, "l": "default", "speed": 1.0, "cfl": 0.5, "grid": "uniform", "set": "acst"}
    for p in parts[1:]:
        k, v = p.split("=", 1)
        c[k] = v if k in ("l", "grid", "set") else float(v)
    if c["grid"] not in ("uniform", "graded"):
        sys.exit(f"{text}: grid is uniform or graded")
    if c["set"] not in SETS:
        path = os.path.join(ROOT, c["set"])
        stem = os.path.splitext(os.path.basename(c["set"]))[0]
        if not (c["set"].endswith(".json") and os.path.isfile(path) and re.fullmatch(r"[A-Za-z0-9_.-]+", stem)):
            sys.exit(f"{text}: set is one of {', '.join(SETS)} or an existing material file FILE.json (a plain stem) "
                     "relative to the repository")
        SETS[stem] = path
        c["set"] = stem
    for key in ("largest", "window"):
        if key in c and c["grid"] != "graded":
            sys.exit(f"{text}: {key} needs grid=graded")
    tag = f"{c['test']}_h{c['h']:g}_l{c['l']}_v{c['speed']:g}_cfl{c['cfl']:g}"
    for key in ("largest", "window", "m", "lc", "kc"):
        if key in c:
            tag += f"_{key}{c[key]:g}"
    if c["grid"] == "graded":
        tag += "_graded"
    if c["set"] != "acst":
        tag += "_" + c["set"]
    c["name"] = tag.replace(".", "p")
    return c


def scene_of(c, stop, threads):
    body = KIMURA_TESTS[c["test"]]
    base = BASE[c["test"]] if c["test"] in BASE else BASE["H86.7" if body["bedding_angle_deg"] == 90 else "V85.6"]
    s = scene_with_absolute_paths(os.path.join(SCENES, base))
    s["bodies"][0].update(body)
    if c["test"] not in BASE:  # a test without a convergence scene of its own has no digitised curve either
        s["description"] = (f"Kimura et al. (1985) test {c['test']}: the convergence scene {base} with the sand of the "
                            "reference study's sweep (data/sweeps/reference_study.json)")
        for key in ("lab_curve", "lab_label"):
            s["output"].pop(key, None)
    s["name"] = c["name"]
    s["grid"]["cell_size"] = c["h"]
    s["footing"]["speed"] *= c["speed"]
    s["solver"]["cfl"] = c["cfl"]
    s["solver"]["threads"] = threads
    s["stop"] = {"S_over_B": stop}
    s["output"]["checkpoint_every_s"] = 600
    if SETS[c["set"]]:
        s["materials"] = {k: SETS[c["set"]] for k in s["materials"]}
    if c["grid"] == "graded":
        s["grid"]["graded"] = {}  # the documented window, growth and largest cell
        if "largest" in c:
            s["grid"]["graded"]["largest_cell"] = c["largest"]
        if "window" in c:
            s["grid"]["graded"]["window_half_width_B"] = s["grid"]["graded"]["window_depth_B"] = c["window"]
    if c["l"] == "default":
        s["regularisation"] = {"acceleration_level": 30}  # Kimura's centrifuge; Toyoura's d50
    elif float(c["l"]) > 0:
        s["regularisation"] = {"internal_length_m": float(c["l"])}
    if "m" in c:
        if "regularisation" not in s:
            sys.exit(f"{c['name']}: m needs a regularisation (l > 0)")
        s["regularisation"]["over_nonlocal"] = c["m"]
    if c.get("lc", 0) > 0:
        s["micropolar"] = {"length_m": c["lc"], "modulus_ratio": c.get("kc", 0.5)}
    elif "kc" in c:
        sys.exit(f"{c['name']}: kc needs micropolar rotations (lc > 0)")
    return s


def interpolate(S, q, at):
    for i in range(1, len(S)):
        if S[i - 1] <= at <= S[i]:
            return q[i - 1] + (q[i] - q[i - 1]) * (at - S[i - 1]) / (S[i] - S[i - 1])
    return float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "footing_regularised"))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--stop", type=float, default=0.25, help="S/B to run to")
    ap.add_argument("--tool", default=os.path.join(ROOT, "build", "mpm_adapter", "acst_mpm"))
    ap.add_argument("--no-run", action="store_true",
                    help="run nothing: tabulate the cases OUT holds, a run that stopped early from its failure record")
    ap.add_argument("cases", nargs="+")
    a = ap.parse_args()
    os.makedirs(os.path.join(a.out, "scenes"), exist_ok=True)
    rows = []
    for text in a.cases:
        c = parse_case(text)
        run_dir = os.path.join(a.out, c["name"])
        summary_file = os.path.join(run_dir, "summary.json")
        failed_record = os.path.join(run_dir, "load_settlement.failed.csv")
        if a.no_run and not os.path.exists(summary_file):
            if os.path.exists(failed_record):
                S, q = read_curve(failed_record)
                k = max(range(len(S)), key=lambda i: q[i])
                rows.append({"case": c["name"], "grid": c["grid"], "set": c["set"], "cell_m": c["h"], "internal_length_m": c["l"],
                             "speed_factor": c["speed"], "cfl": c["cfl"], "q_ult_kPa": round(q[k], 1),
                             "S_ult_over_B": round(S[k], 4), "q_at_SB0.1_kPa": round(interpolate(S, q, 0.1), 1),
                             "final_S_over_B": round(S[-1], 4), "status": f"stopped at S/B {S[-1]:.3f} (load_settlement.failed.csv)"})
            continue
        _, failure = run_case(a.tool, a.out, c["name"], scene_of(c, a.stop, a.threads))
        if failure:
            rows.append({"case": c["name"], "cell_m": c["h"], "status": failure})
            print(json.dumps(rows[-1]), flush=True)
            continue
        with open(summary_file) as f:
            s = json.load(f)
        S, q = read_curve(os.path.join(run_dir, "load_settlement.csv"))
        with open(os.path.join(a.out, "scenes", c["name"] + ".json")) as f:
            scene = json.load(f)
        l = scene.get("regularisation", {}).get("internal_length_m", None)
        r = {"case": c["name"], "grid": c["grid"], "set": c["set"], "cell_m": c["h"], "internal_length_m": 0.0 if c["l"] == "0" else (l if l else "default"),
             "speed_factor": c["speed"], "cfl": c["cfl"], "q_ult_kPa": round(s["q_ult_kPa"], 1),
             "S_ult_over_B": round(s["S_ult_over_B"], 4), "wall_s": round(s["wall_s"], 1),
             "q_first_peak_kPa": s["q_first_peak_kPa"] and round(s["q_first_peak_kPa"], 1),
             "S_first_peak_over_B": s["S_first_peak_over_B"] and round(s["S_first_peak_over_B"], 4),
             "q_at_SB0.1_kPa": round(interpolate(S, q, 0.1), 1), "q_at_SB0.25_kPa": round(interpolate(S, q, 0.25), 1),
             "final_S_over_B": round(s["final_S_over_B"], 4), "max_kinetic_ratio": s["max_kinetic_ratio"], "status": "done"}
        rows.append(r)
        print(json.dumps(r), flush=True)
    write_table_and_figures(a.out, rows)


LOCAL = os.path.join(ROOT, "bench", "results", "footing_convergence", "convergence.csv")


def write_table_and_figures(out, rows):
    table = os.path.join(out, "convergence.csv")
    old = old_rows(table, rows)
    # The local model's rows are its cell-size study's (bench/results/footing_convergence/: the same
    # scenes, speed and CFL, and the same numbers as today's local code), not run again.
    with open(LOCAL) as f:
        local = [r for r in csv.DictReader(f) if "ppc" not in r["scene"]]
    local_rows = [{"case": r["scene"], "cell_m": r["cell"], "internal_length_m": 0.0, "speed_factor": 1.0, "cfl": 0.5,
                   "q_ult_kPa": r["q_ult_kPa"], "S_ult_over_B": r["S_ult_over_B"], "wall_s": r["wall_s"],
                   "q_first_peak_kPa": r["q_first_peak_kPa"], "S_first_peak_over_B": r["S_first_peak_over_B"],
                   "status": "done (bench/results/footing_convergence, to S/B 0.5)"} for r in local]
    old = [r for r in old if not r["status"].startswith("done (")]
    write_table(table, FIELDS, old + rows + local_rows)
    with open(table) as f:
        every = [r for r in csv.DictReader(f) if r["status"] == "done" or r["status"].startswith("stopped")]
    for r in every:  # rows of tables written before the grid and set columns
        r["grid"] = r.get("grid") or "uniform"
        r["set"] = r.get("set") or "acst"
    # The series of each figure: the regularised runs at the default internal length, the study's
    # speed and CFL and m = 1, by grid and parameter set.
    series = [("uniform", "acst", "regularised, uniform grid"), ("graded", "acst", "regularised, graded grid (3 B window)"),
              ("graded", "isotropic", "regularised, graded grid, isotropic set")]
    def reference_runs(test, grid, kind):
        return sorted((float(r["cell_m"]), r["case"], float(r["q_ult_kPa"])) for r in every
                      if r["case"].startswith(test.replace(".", "p")) and r["internal_length_m"] == "default"
                      and float(r["speed_factor"]) == 1.0 and float(r["cfl"]) == 0.5 and r["grid"] == grid
                      and r["set"] == kind and "_m" not in r["case"].split("_cfl")[1]
                      and (grid == "uniform" or "window3" in r["case"]))
    # q_ult against the cell: the local model's study and the regularised runs at the default
    # internal length, the study's speed and CFL.
    lines = ["set terminal pngcairo size 1300,520 noenhanced", f"set output {gp_quoted(os.path.join(out, 'q_ult_against_h.png'))}",
             "set multiplot layout 1,2", "set grid", "set key bottom right", "set xlabel 'cell size h [m]'",
             "set ylabel 'q_ult [kPa]'", "set xrange [0:0.2]", "set yrange [0:2800]",
             # The biaxial test's resolution: a band independent of the cell from h = l/2 down.
             "set arrow from 0.0425, graph 0 to 0.0425, graph 1 nohead dt 3",
             "set label 'h = l/2' at 0.0445, graph 0.05"]
    kimura = {"V85.6": 1953, "H86.7": 1734}
    for test in ("V85.6", "H86.7"):
        loc = sorted((float(r["cell"]), float(r["q_ult_kPa"])) for r in local if r["test"] == test)
        data = lambda pts: "\n".join(f"{x} {y}" for x, y in pts) + "\ne"
        present = [(title, [(h, q) for h, _, q in reference_runs(test, g, k)]) for g, k, title in series]
        present = [(title, pts) for title, pts in present if pts]
        lines += [f"set title {gp_quoted(test + ': the largest load against the cell (S/B up to 0.25; l = 0.085 m)')}",
                  "plot '-' using 1:2 with linespoints lw 2 pt 7 title 'local (ACST, no internal length)', " +
                  "".join(f"'-' using 1:2 with linespoints lw 2 pt {5 + i} title {gp_quoted(title)}, "
                          for i, (title, _) in enumerate(present)) +
                  f"{kimura[test]} with lines dt 2 lc rgb 'black' title 'Kimura et al. (1985)'",
                  data(loc)] + [data(pts) for _, pts in present]
    lines += ["unset multiplot", ""]
    # Each test's regularised curves at the study's speed and CFL over the centrifuge's.
    for test in ("V85.6", "H86.7"):
        runs = [(h, case, g) for g, k, _ in series[:2] for h, case, _ in reference_runs(test, g, k)]
        if not runs:
            continue
        lab = os.path.join(ROOT, "data", "lab", "kimura_1985", test + ".csv")
        records = [(h, g, next((p for p in (os.path.join(out, case, n) for n in ("load_settlement.csv", "load_settlement.failed.csv"))
                                if os.path.exists(p)), None)) for h, case, g in runs]
        curves = [(f"{g}, h = {h:g} m", read_curve(p)) for h, g, p in records if p]
        curves.append(("Kimura et al. (1985)", read_curve(lab)))
        lines += ["unset arrow", "unset label", "set terminal pngcairo size 900,600 noenhanced", f"set output {gp_quoted(os.path.join(out, test + '_curves.png'))}",
                  "set grid", "set key top right", "set xlabel 'S/B'", "set ylabel 'q [kPa]'", "set xrange [0:0.25]",
                  "set yrange [0:2600]", f"set title {gp_quoted(test + ': regularised (l = 0.085 m) against the centrifuge')}",
                  "plot " + ", ".join(f"'-' using 1:2 with lines lw 2 title {gp_quoted(name)}" for name, _ in curves[:-1]) +
                  f", '-' using 1:2 with points pt 7 ps 0.5 lc rgb 'black' title {gp_quoted(curves[-1][0])}"]
        for _, (S, q) in curves:
            step = max(1, len(S) // 2000)  # a few thousand points draw the curve
            lines.append("\n".join(f"{a} {b}" for a, b in zip(S[::step], q[::step])) + "\ne")
    subprocess.run(["gnuplot"], input="\n".join(lines), text=True, check=False)
    plot_lengths(out, every)


def plot_lengths(out, every):
    """V85.6's largest and first-peak load against the cell on the graded grid for each internal
    length (0: the local model), at the study's speed and CFL and m = 1: the length's sensitivity."""
    def length_of(r):
        return 0.085 if r["internal_length_m"] == "default" else float(r["internal_length_m"])
    chosen = [r for r in every if r["case"].startswith("V85p6") and r["grid"] == "graded" and r["set"] == "acst"
              and float(r["speed_factor"]) == 1.0 and float(r["cfl"]) == 0.5 and "_m" not in r["case"].split("_cfl")[1]]
    lengths = sorted({length_of(r) for r in chosen})
    if not lengths:
        return
    lines = ["set terminal pngcairo size 1400,560 noenhanced", f"set output {gp_quoted(os.path.join(out, 'q_ult_against_h_by_length.png'))}",
             "set multiplot layout 1,2", "set grid", "set key bottom right", "set xlabel 'cell size h [m]'",
             "set xrange [0:0.1]", "set yrange [900:1700]"]
    for column, what in (("q_ult_kPa", "the largest load"), ("q_first_peak_kPa", "the first peak")):
        data = [sorted((float(r["cell_m"]), float(r[column])) for r in chosen if length_of(r) == l and r.get(column)) for l in lengths]
        lines += [f"set ylabel {gp_quoted(column.replace('_kPa', '') + ' [kPa]')}",
                  f"set title {gp_quoted(f'V85.6, graded grid: {what} against the cell for each internal length l')}",
                  "plot " + ", ".join(f"'-' using 1:2 with linespoints lw 2 pt 7 title {gp_quoted('local (l = 0)' if l == 0 else f'l = {l:g} m')}"
                                     for l in lengths)]
        lines += ["\n".join(f"{h} {q}" for h, q in pts) + "\ne" for pts in data]
    lines += ["unset multiplot", ""]
    subprocess.run(["gnuplot"], input="\n".join(lines), text=True, check=False)


if __name__ == "__main__":
    main()
