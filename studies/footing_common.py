"""Helpers shared by the studies in studies/ (command line, the runs of acst_mpm cases, load
curves, tables, gnuplot quoting)."""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def study_arguments(doc, out_name, only_help, switches=()):
    """The command line of a study that runs acst_mpm cases: --out, --threads, --only, --tool, and
    the study's own on/off `switches`, (flag, help) pairs."""
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", out_name))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--only", default="", help=only_help)
    ap.add_argument("--tool", default=os.path.join(ROOT, "build", "mpm_adapter", "acst_mpm"))
    for flag, text in switches:
        ap.add_argument(flag, action="store_true", help=text)
    return ap.parse_args()


def tool_arguments(doc, out_name, tool, options=()):
    """The command line of a study that runs one of the project's tools: --out (default
    bench/results/OUT_NAME, made absolute, as the descriptions the study writes name files in it),
    --tool (default build/TOOL, e.g. "calibration/acst_fit") and the study's `options`, (flag,
    keyword arguments) pairs."""
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", out_name))
    ap.add_argument("--tool", default=os.path.join(ROOT, "build", tool))
    for flag, kw in options:
        ap.add_argument(flag, **kw)
    a = ap.parse_args()
    a.out = os.path.abspath(a.out)
    return a


def footing_cases_arguments(doc, out, stop, extra=()):
    """The command line of a study of footing cases: --out (default `out`), --threads, --stop
    (default `stop`), --tool, the study's `extra` (flag, keyword arguments) pairs and CASE ...."""
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    for flag, kw in extra:
        ap.add_argument(flag, **kw)
    ap.add_argument("--out", default=out)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--stop", type=float, default=stop, help="S/B to run to")
    ap.add_argument("--tool", default=os.path.join(ROOT, "build", "mpm_adapter", "acst_mpm"))
    ap.add_argument("cases", nargs="+")
    return ap.parse_args()


def scene_with_absolute_paths(path):
    """A scene file as a dict, its parameter files and lab curve made absolute (they are relative
    to the scene's folder), so that a changed copy can be written anywhere."""
    with open(path) as f:
        s = json.load(f)
    here = os.path.dirname(os.path.abspath(path))
    s["materials"] = {k: v if isinstance(v, dict) else os.path.normpath(os.path.join(here, v))
                      for k, v in s["materials"].items()}
    if "lab_curve" in s.get("output", {}):
        s["output"]["lab_curve"] = os.path.normpath(os.path.join(here, s["output"]["lab_curve"]))
    return s


def read_curve(path):
    """S/B and q (kPa) columns of a load_settlement CSV or a lab curve (comment lines start with #)."""
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return [float(r["S_over_B"]) for r in rows], [float(r["q_kPa"]) for r in rows]


def value_at(xs, ys, x):
    """Linear interpolation of ys at x; NaN outside the curve."""
    for i in range(1, len(xs)):
        if xs[i - 1] <= x <= xs[i]:
            t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]) if xs[i] > xs[i - 1] else 0.0
            return ys[i - 1] + t * (ys[i] - ys[i - 1])
    return float("nan")


def gp_quoted(text):
    """A gnuplot single-quoted string: names and paths never become script."""
    return "'" + str(text).replace("'", "''").replace("\n", " ") + "'"


def max_kinetic_ratio(path, from_S_over_B=0.02):
    """The largest kinetic-to-work ratio of a load record from S/B from_S_over_B on (the start's
    transient left out, as acst_mpm's quasi-static check does)."""
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return max(float(r["kinetic_over_work"]) for r in rows if float(r["S_over_B"]) >= from_S_over_B)


def run_study_case(a, name, make_scene, done=("summary.json",), indent=2):
    """Runs acst_mpm (a.tool, --threads a.threads) on case NAME into OUT/NAME (OUT = a.out), its
    scene from make_scene() written to OUT/NAME.json first, unless --only (a.only, in the studies
    that have it) leaves the case out or a file named in `done` exists in OUT/NAME; an exit other
    than 0 is printed. Returns OUT/NAME: a study resumes by calling it for every case again."""
    run_dir = os.path.join(a.out, name)
    only = getattr(a, "only", "")
    if (not only or name in only.split(",")) and not any(os.path.exists(os.path.join(run_dir, f)) for f in done):
        path = os.path.join(a.out, name + ".json")
        with open(path, "w") as f:
            json.dump(make_scene(), f, indent=indent)
        print(f"== {name}", flush=True)
        run = subprocess.run([a.tool, "--quiet", "--no-plot", "--threads", str(a.threads), "--output", run_dir, path])
        if run.returncode != 0:
            print(f"{name}: acst_mpm exit {run.returncode}", file=sys.stderr)
    return run_dir


def rms_difference_pct(curve, ref_curve, upto, q_scale):
    """RMS of curve - ref_curve over S/B 0.005..upto in steps of 0.005, in % of q_scale; points
    outside either record (a record averaged over long periods starts late) are left out."""
    grid = [0.005 * k for k in range(1, int(round(upto / 0.005)) + 1)]
    d = [value_at(*curve, x) - value_at(*ref_curve, x) for x in grid]
    d = [v for v in d if not math.isnan(v)]
    return round(100.0 * math.sqrt(sum(v * v for v in d) / len(d)) / q_scale, 2)


def add_rms_to_reference(table, reference_of, windows):
    """Puts into each row of `table` (a dict with its "curve") rms_to_UPTO_pct for each S/B UPTO
    in `windows`: the RMS difference from the row reference_of(row) over S/B 0.005-UPTO in % of
    that row's largest load, q_max_kPa (rms_difference_pct); "" where reference_of gives None."""
    for r in table:
        ref = reference_of(r)
        for upto in windows:
            r[f"rms_to_{upto}_pct"] = "" if ref is None else rms_difference_pct(r["curve"], ref["curve"], upto, ref["q_max_kPa"])


def write_table(path, fields, rows):
    """A CSV of the columns FIELDS of dict rows (other keys, e.g. curves, left out)."""
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)


def plot_beside_kimura(png, panels, stop_s_over_b, key="bottom right"):
    """One panel per Kimura test, {test: (title, [(load record, label), ...])}, each with the
    test's measured curve where data/lab/kimura_1985/TEST.csv holds one."""
    lines = [f"set terminal pngcairo size {700 * len(panels)},600 noenhanced", "set datafile separator ','",
             "set datafile commentschars '#'", f"set output {gp_quoted(png)}", f"set multiplot layout 1,{len(panels)}",
             "set grid", f"set key {key}", "set xlabel 'S/B'", "set ylabel 'q = V/B [kPa]'",
             f"set xrange [0:{stop_s_over_b}]", "set yrange [0:2600]"]
    for test, (title, curves) in panels.items():
        plots = [f"{gp_quoted(record)} using 'S_over_B':'q_kPa' with lines lw 2 title {gp_quoted(label)}" for record, label in curves]
        lab = os.path.join(ROOT, "data", "lab", "kimura_1985", test + ".csv")
        if os.path.isfile(lab):
            plots.append(f"{gp_quoted(lab)} using 'S_over_B':'q_kPa' with points pt 7 ps 0.6 lc rgb 'black' "
                         f"title {gp_quoted('Kimura et al. (1985) ' + test)}")
        lines += [f"set title {gp_quoted(title)}", "plot " + ", ".join(plots)]
    lines += ["unset multiplot", ""]
    subprocess.run(["gnuplot"], input="\n".join(lines), text=True, check=False)


def run_case(tool, out, name, scene):
    """Runs acst_mpm on `scene` into OUT/NAME (the scene written to OUT/scenes/NAME.json first),
    unless OUT/NAME/summary.json exists. Returns the case's folder and None, or the folder and
    the failure's text."""
    run_dir = os.path.join(out, name)
    if os.path.exists(os.path.join(run_dir, "summary.json")):
        return run_dir, None
    os.makedirs(os.path.join(out, "scenes"), exist_ok=True)
    path = os.path.join(out, "scenes", name + ".json")
    with open(path, "w") as f:
        json.dump(scene, f, indent=1)
    run = subprocess.run([tool, "--quiet", "--output", run_dir, path], capture_output=True, text=True)
    return run_dir, None if run.returncode == 0 else "failed: " + run.stderr.strip()[:200]


def run_and_read(tool, out, name, scene, cell, rows):
    """Runs a case (run_case) and returns its folder, its summary and its load curve (S/B, q); a
    case that failed is appended to rows (its name, cell and failure), printed, and gives None."""
    run_dir, failure = run_case(tool, out, name, scene)
    if failure:
        rows.append({"case": name, "cell_m": cell, "status": failure})
        print(json.dumps(rows[-1]), flush=True)
        return None
    with open(os.path.join(run_dir, "summary.json")) as f:
        summary = json.load(f)
    return run_dir, summary, read_curve(os.path.join(run_dir, "load_settlement.csv"))


def old_rows(path, rows):
    """The rows of the CSV at path (if any) whose case is not among rows' (they are replaced)."""
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [r for r in csv.DictReader(f) if r["case"] not in {x["case"] for x in rows}]
