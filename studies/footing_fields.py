#!/usr/bin/env python3
"""Maps of particle fields of footing runs side by side (docs/footing-study.md, "The Kimura footings with the contact footing").

Reads the ParaView snapshots (particles.pvd / particles_NNNN.vtp) of each run folder, takes the
snapshot nearest to the settlement asked for (S/B from the run's load_settlement.csv), and writes
OUT/<field>_SB<S/B>.png with one panel per run (the soil within 3 B of the footing, where the
mechanism lies) and OUT/<field>_SB<S/B>.csv with the values plotted.

  python3 studies/footing_fields.py --out DIR --at 0.1 [--field fabric_norm,N,...] LABEL=RUN_DIR ...

Fields: any scalar the runs write (shear_strain, fabric_norm, N, void_ratio, p_kPa, q_kPa, ...).
"""
import argparse
import bisect
import csv
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

from footing_common import gp_quoted

RANGES = {"N": (-1.0, 1.0)}


def snapshot_near(run_dir, s_over_b):
    with open(os.path.join(run_dir, "load_settlement.csv")) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    times = [float(r["time_s"]) for r in rows]
    sb = [float(r["S_over_B"]) for r in rows]
    k = min(range(len(sb)), key=lambda i: abs(sb[i] - s_over_b))
    t = times[k]
    pvd = ET.parse(os.path.join(run_dir, "particles.pvd")).getroot()
    sets = [(float(d.get("timestep")), d.get("file")) for d in pvd.iter("DataSet")]
    best = min(sets, key=lambda s: abs(s[0] - t))
    # the settlement at the snapshot's time, for the panel's title
    j = min(bisect.bisect_left(times, best[0]), len(times) - 1)
    return os.path.join(run_dir, best[1]), sb[j]


def read_vtp(path, names):
    root = ET.parse(path).getroot()
    points = root.find(".//Points/DataArray")
    xyz = [float(v) for v in points.text.split()]
    x, y = xyz[0::3], xyz[1::3]
    out = {}
    for a in root.iter("DataArray"):
        if a.get("Name") in names:
            out[a.get("Name")] = [float(v) for v in a.text.split()]
    missing = [n for n in names if n not in out]
    if missing:
        raise SystemExit(f"{path}: no field {', '.join(missing)}")
    return x, y, out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True)
    ap.add_argument("--at", type=float, required=True, help="S/B of the snapshot")
    ap.add_argument("--field", default="shear_strain,fabric_norm,N")
    ap.add_argument("--centre", type=float, default=6.3, help="footing centre x (m)")
    ap.add_argument("--top", type=float, default=6.3, help="soil surface y (m)")
    ap.add_argument("--half", type=float, default=2.7, help="half-width of the window (m)")
    ap.add_argument("--depth", type=float, default=2.2, help="depth of the window (m)")
    ap.add_argument("runs", nargs="+", help="LABEL=RUN_DIR")
    a = ap.parse_args()
    fields = a.field.split(",")
    for f in fields:
        if not re.fullmatch(r"[A-Za-z0-9_]+", f):
            raise SystemExit(f"--field: '{f}' is not a plain field name")
    os.makedirs(a.out, exist_ok=True)
    tag = f"SB{a.at:.3f}"
    panels = []
    for r in a.runs:
        label, run_dir = r.split("=", 1)
        path, sb = snapshot_near(run_dir, a.at)
        x, y, vals = read_vtp(path, fields)
        keep = [i for i in range(len(x)) if abs(x[i] - a.centre) <= a.half and y[i] >= a.top - a.depth]
        panels.append((f"{label}, S/B {sb:.3f}", [x[i] for i in keep], [y[i] for i in keep], {f: [vals[f][i] for i in keep] for f in fields}))
    for f in fields:
        csv_path = os.path.join(a.out, f"{f}_{tag}.csv")
        with open(csv_path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["panel", "x_m", "y_m", f])
            for k, (title, xs, ys, v) in enumerate(panels):
                for i in range(len(xs)):
                    w.writerow([k, xs[i], ys[i], v[f][i]])
        if f in RANGES:
            lo, hi = RANGES[f]
        else:
            every = sorted(v for p in panels for v in p[3][f])
            lo, hi = every[0], every[int(0.99 * (len(every) - 1))]
            if hi <= lo:  # a uniform field (the initial fabric): any range around it
                lo, hi = lo - 0.5 * abs(lo) - 1e-9, hi + 0.5 * abs(hi) + 1e-9
        gp = ["set terminal pngcairo size 1100,%d font 'DejaVu Sans,11' noenhanced" % (420 * len(panels)),
              "set output " + gp_quoted(os.path.join(a.out, f"{f}_{tag}.png")),
              "set datafile separator ','", "set size ratio -1", f"set cbrange [{lo}:{hi}]",
              "set palette rgb 33,13,10", "set xlabel 'x [m]'", "set ylabel 'y [m]'",
              f"set multiplot layout {len(panels)},1"]
        for k, (title, _, _, _) in enumerate(panels):
            gp += ["set title " + gp_quoted(title + ": " + f),
                   f"plot {gp_quoted(csv_path)} using ($1=={k} ? $2 : 1/0):3:4 every ::1 with points pt 5 ps 0.45 lc palette notitle"]
        gp.append("unset multiplot")
        subprocess.run(["gnuplot"], input="\n".join(gp), text=True, check=True)
        print(os.path.join(a.out, f"{f}_{tag}.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
