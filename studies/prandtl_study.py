#!/usr/bin/env python3
"""Prandtl's bearing capacity with the contact footing (docs/mpm.md, "The footing").

A rigid strip (B = 1 m) on weightless Tresca soil (4 B x 2 B, s_u = 10 kPa, E = 1000 s_u; the
scene of tests/mpm_adapter/core/footing_test.cpp). q = V/B averaged over S/B 0.02-0.05 against (2 + pi) s_u:
  - cells B/10, B/20, B/40 at 0.02 m/s (rough; smooth at B/10), with the extrapolated limits;
  - the same cells, rough and smooth, with the grid's rows following the footing's base
    (grid/follow_footing; docs/mpm.md, "The grid follows the footing");
  - at B/10, the particle update (FLIP, XPIC every 100/20/5 steps, PIC) at 0.1 m/s and the
    loading speed (0.1, 0.02, 0.01 m/s) for the default XPIC and for PIC.
  - at B/10 and 0.02 m/s, what sets the error: particles per cell (with and without the
    cell-averaged dilation rate, solver/volumetric_averaging; also at B/20), Poisson's ratio, stiffness
    (E = 300 s_u, over S/B 0.10-0.15, past its later failure), the footing's edges a quarter and
    half a cell off the nodes, the node-row footing, and the load further on (S/B 0.05-0.25);
    with the rows following: Coulomb friction, the edges half a cell off, node rows, 0.01 m/s and
    the load further on.
  - where the scene is what Prandtl's solution describes (docs/footing-study.md, "What Prandtl's load
    measures"): E = 10^4 s_u, which collapses by S/B 0.003, every step's load over S/B 0.005-0.01;
    the particle update's filter every 20, 100, 500, 1000 steps and FLIP alone, rows following and
    fixed, B/10 and B/20, rough and smooth.
Writes OUT/prandtl.csv and OUT/prandtl.png (q over Prandtl against h/B). B/40 takes minutes.

  python3 studies/prandtl_study.py [--out DIR] [--threads N] [--tool PATH]
"""
import argparse
import csv
import math
import os
import subprocess
import sys

from footing_common import gp_quoted, read_curve, run_study_case

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PRANDTL = (2 + math.pi) * 10.0  # kPa

# name, cell size (m), interface, speed (m/s), particle update, XPIC every[, rows follow the footing]
CASES = [
    ("rough_h010", 0.1, "rough", 0.02, "XPIC", 20),
    ("rough_h005", 0.05, "rough", 0.02, "XPIC", 20),
    ("rough_h0025", 0.025, "rough", 0.02, "XPIC", 20),
    ("smooth_h010", 0.1, "smooth", 0.02, "XPIC", 20),
    ("flip_v010", 0.1, "rough", 0.1, "FLIP", 20),
    ("xpic100_v010", 0.1, "rough", 0.1, "XPIC", 100),
    ("xpic20_v010", 0.1, "rough", 0.1, "XPIC", 20),
    ("xpic5_v010", 0.1, "rough", 0.1, "XPIC", 5),
    ("pic_v010", 0.1, "rough", 0.1, "PIC", 20),
    ("xpic20_v001", 0.1, "rough", 0.01, "XPIC", 20),
    ("pic_v002", 0.1, "rough", 0.02, "PIC", 20),
    ("pic_v001", 0.1, "rough", 0.01, "PIC", 20),
    ("follow_rough_h010", 0.1, "rough", 0.02, "XPIC", 20, True),
    ("follow_rough_h005", 0.05, "rough", 0.02, "XPIC", 20, True),
    ("follow_rough_h0025", 0.025, "rough", 0.02, "XPIC", 20, True),
    ("follow_smooth_h010", 0.1, "smooth", 0.02, "XPIC", 20, True),
    ("follow_smooth_h005", 0.05, "smooth", 0.02, "XPIC", 20, True),
    ("follow_smooth_h0025", 0.025, "smooth", 0.02, "XPIC", 20, True),
]

# At B/10, rough, 0.02 m/s, XPIC every 20: name, what differs (scene keys), averaging window, stop.
VARIANTS = [
    ("ppc2_h010", {"bodies/0/particles_per_cell": 2}, (0.02, 0.05), 0.05),
    ("ppc3_h010", {"bodies/0/particles_per_cell": 3}, (0.02, 0.05), 0.05),
    ("nu0_h010", {"materials/clay/parameters/nu": 0.0}, (0.02, 0.05), 0.05),
    ("nu049_h010", {"materials/clay/parameters/nu": 0.49}, (0.02, 0.05), 0.05),
    ("E1000su_late_h010", {}, (0.10, 0.15), 0.15),
    ("E300su_late_h010", {"materials/clay/parameters/E": 3000}, (0.10, 0.15), 0.15),
    ("edge_quarter_off_h010", {"footing/centre_x": 2.025}, (0.02, 0.05), 0.05),
    ("edge_half_off_h010", {"footing/centre_x": 2.05}, (0.02, 0.05), 0.05),
    ("node_rows_h010", {"footing/contact": "node_rows"}, (0.02, 0.05), 0.05),
    ("long_h010", {}, (0.05, 0.25), 0.25),
    # with the rows following the footing: what is left of the error
    ("follow_coulomb03_h010", {"grid/follow_footing": True, "footing/interface": "coulomb",
                               "footing/friction_coefficient": 0.3}, (0.02, 0.05), 0.05),
    ("follow_coulomb1_h010", {"grid/follow_footing": True, "footing/interface": "coulomb",
                              "footing/friction_coefficient": 1.0}, (0.02, 0.05), 0.05),
    ("follow_edge_half_off_h010", {"grid/follow_footing": True, "footing/centre_x": 2.05}, (0.02, 0.05), 0.05),
    ("follow_node_rows_h010", {"grid/follow_footing": True, "footing/contact": "node_rows"}, (0.02, 0.05), 0.05),
    ("follow_v001_h010", {"grid/follow_footing": True, "footing/speed": 0.01}, (0.02, 0.05), 0.05),
    ("follow_long_h010", {"grid/follow_footing": True}, (0.05, 0.25), 0.25),
    ("follow_flip_h010", {"grid/follow_footing": True, "solver/particle_update": "FLIP"}, (0.02, 0.05), 0.05),
    ("follow_smooth_flip_h010", {"grid/follow_footing": True, "footing/interface": "smooth",
                                 "solver/particle_update": "FLIP"}, (0.02, 0.05), 0.05),
    # volumetric locking at several particles per cell and the cell-averaged dilation rate
    # (solver/volumetric_averaging; docs/mpm.md, "Volumetric locking")
    ("ppc2_cell_h010", {"bodies/0/particles_per_cell": 2, "solver/volumetric_averaging": "cell"}, (0.02, 0.05), 0.05),
    ("ppc3_cell_h010", {"bodies/0/particles_per_cell": 3, "solver/volumetric_averaging": "cell"}, (0.02, 0.05), 0.05),
    ("ppc1_cell_h010", {"solver/volumetric_averaging": "cell"}, (0.02, 0.05), 0.05),
    ("ppc2_h005", {"grid/cell_size": 0.05, "bodies/0/particles_per_cell": 2}, (0.02, 0.05), 0.05),
    ("ppc2_cell_h005", {"grid/cell_size": 0.05, "bodies/0/particles_per_cell": 2,
                        "solver/volumetric_averaging": "cell"}, (0.02, 0.05), 0.05),
    ("smooth_ppc2_h010", {"footing/interface": "smooth", "bodies/0/particles_per_cell": 2}, (0.02, 0.05), 0.05),
    ("smooth_ppc2_cell_h010", {"footing/interface": "smooth", "bodies/0/particles_per_cell": 2,
                               "solver/volumetric_averaging": "cell"}, (0.02, 0.05), 0.05),
    ("follow_ppc2_h010", {"grid/follow_footing": True, "bodies/0/particles_per_cell": 2}, (0.02, 0.05), 0.05),
    ("follow_ppc2_cell_h010", {"grid/follow_footing": True, "bodies/0/particles_per_cell": 2,
                               "solver/volumetric_averaging": "cell"}, (0.02, 0.05), 0.05),
    ("follow_ppc3_h010", {"grid/follow_footing": True, "bodies/0/particles_per_cell": 3}, (0.02, 0.05), 0.05),
    ("follow_ppc3_cell_h010", {"grid/follow_footing": True, "bodies/0/particles_per_cell": 3,
                               "solver/volumetric_averaging": "cell"}, (0.02, 0.05), 0.05),
    ("follow_smooth_ppc2_h010", {"grid/follow_footing": True, "footing/interface": "smooth",
                                 "bodies/0/particles_per_cell": 2}, (0.02, 0.05), 0.05),
    ("follow_smooth_ppc2_cell_h010", {"grid/follow_footing": True, "footing/interface": "smooth",
                                      "bodies/0/particles_per_cell": 2, "solver/volumetric_averaging": "cell"},
     (0.02, 0.05), 0.05),
    ("follow_ppc2_cell_h005", {"grid/cell_size": 0.05, "grid/follow_footing": True, "bodies/0/particles_per_cell": 2,
                               "solver/volumetric_averaging": "cell"}, (0.02, 0.05), 0.05),
    ("follow_smooth_ppc2_cell_h005", {"grid/cell_size": 0.05, "grid/follow_footing": True,
                                      "footing/interface": "smooth", "bodies/0/particles_per_cell": 2,
                                      "solver/volumetric_averaging": "cell"}, (0.02, 0.05), 0.05),
]

# E = 10^4 s_u, every step's load averaged over S/B 0.005-0.01, to S/B 0.012: name, cell size,
# interface, rows follow the footing, particle update, XPIC every, speed (m/s). The ladders: rows
# following or fixed, the cell, and the particle updates run for each interface.
RIGID_PLASTIC_LADDERS = ((True, 0.1, ("xpic20", "xpic100", "xpic500", "xpic1000", "flip")),
                         (True, 0.05, ("xpic20", "xpic500", "flip")),
                         (False, 0.1, ("xpic20", "xpic500", "flip")),
                         (False, 0.05, ("xpic500",)))
RIGID_PLASTIC = [
    (f"rp_{'follow' if follow else 'fixed'}_{interface}_h{round(h * 100):03d}_{update}", h, interface, follow,
     "FLIP" if update == "flip" else "XPIC", 20 if update == "flip" else int(update[len("xpic"):]), 0.02)
    for follow, h, updates in RIGID_PLASTIC_LADDERS for interface in ("rough", "smooth") for update in updates
] + [("rp_follow_rough_h010_xpic20_v0005", 0.1, "rough", True, "XPIC", 20, 0.005),
     ("rp_follow_rough_h010_xpic500_v001", 0.1, "rough", True, "XPIC", 500, 0.01)]


def with_changes(s, changes, stop):
    for path, value in changes.items():
        *parents, key = path.split("/")
        node = s
        for part in parents:
            node = node[int(part)] if part.isdigit() else node[part]
        node[key] = value
    s["stop"]["S_over_B"] = stop
    return s


def scene(name, h, interface, speed, update, every, follow=False):
    return {"name": name, "grid": {"cell_size": h, "follow_footing": follow},
            "materials": {"clay": {"model": "von_mises",
                                   "parameters": {"E": 10000, "nu": 0.3, "undrained_shear_strength": 10}}},
            "bodies": [{"material": "clay", "x_range": [0, 4], "y_range": [0, 2], "density": 1000}],
            "footing": {"width": 1.0, "centre_x": 2.0, "speed": speed, "interface": interface, "contact": "penalty"},
            "solver": {"grid_damping": 2, "particle_update": update, "xpic_order": 4, "xpic_every": every},
            "output": {"vtk_every_S_over_B": 0.05},
            "stop": {"S_over_B": 0.05}}


def mean_q(S, q, lo, hi):
    v = [b for a, b in zip(S, q) if lo <= a <= hi]
    return sum(v) / len(v) if v else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "prandtl"))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--tool", default=os.path.join(ROOT, "build", "mpm_adapter", "acst_mpm"))
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    rows = []

    def run(name, description, row, window):
        run_dir = run_study_case(a, name, lambda: description, done=("load_settlement.csv",), indent=1)
        record = os.path.join(run_dir, "load_settlement.csv")
        if not os.path.exists(record):  # the run failed
            return
        S, q = read_curve(record)
        qm = mean_q(S, q, *window)
        row.update({"S_over_B_window": f"{window[0]}-{window[1]}", "q_kPa": round(qm, 2),
                    "q_over_prandtl": round(qm / PRANDTL, 4)})
        rows.append(row)
        print(f"{name:22s} {row['variant'] or ''} h/B {row['h_over_B']:<6} {row['interface']:6s} "
              f"{row['speed_m_per_s']:5} m/s {row['particle_update']:4s}  q {qm:6.2f} kPa  q/(2+pi)s_u {qm / PRANDTL:.3f}")

    for name, h, interface, speed, update, every, *follow in CASES:
        follow = bool(follow and follow[0])
        run(name, scene(name, h, interface, speed, update, every, follow),
            {"case": name, "variant": "", "h_over_B": h, "interface": interface, "speed_m_per_s": speed,
             "particle_update": update, "xpic_every": every if update == "XPIC" else "", "rows_follow": follow},
            (0.02, 0.05))
    for name, changes, window, stop in VARIANTS:
        variant = "; ".join(f"{k} = {v}" for k, v in changes.items()) or "as rough_h010"
        update = changes.get("solver/particle_update", "XPIC")
        run(name, with_changes(scene(name, 0.1, "rough", 0.02, "XPIC", 20), changes, stop),
            {"case": name, "variant": variant, "h_over_B": changes.get("grid/cell_size", 0.1),
             "interface": changes.get("footing/interface", "rough"), "speed_m_per_s": changes.get("footing/speed", 0.02),
             "particle_update": update, "xpic_every": 20 if update == "XPIC" else "",
             "rows_follow": changes.get("grid/follow_footing", False)}, window)
    for name, h, interface, follow, update, every, speed in RIGID_PLASTIC:
        description = with_changes(scene(name, h, interface, speed, update, every, follow),
                                   {"materials/clay/parameters/E": 1e5, "output/every_step_csv": True}, 0.012)
        run(name, description,
            {"case": name, "variant": "materials/clay/parameters/E = 100000", "h_over_B": h, "interface": interface,
             "speed_m_per_s": speed, "particle_update": update, "xpic_every": every if update == "XPIC" else "",
             "rows_follow": follow}, (0.005, 0.01))
    with open(os.path.join(a.out, "prandtl.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    plots = []
    for prefix, suffix, title in (
            ("rough_h", "", "fixed rows, rough, E = 1000 s_u, XPIC every 20"),
            ("follow_rough_h", "", "rows follow, rough, E = 1000 s_u, XPIC every 20"),
            ("follow_smooth_h", "", "rows follow, smooth, E = 1000 s_u, XPIC every 20"),
            ("rp_follow_rough_h", "_xpic500", "rows follow, rough, E = 10^4 s_u, XPIC every 500"),
            ("rp_follow_smooth_h", "_xpic500", "rows follow, smooth, E = 10^4 s_u, XPIC every 500")):
        ladder = {r["h_over_B"]: r["q_over_prandtl"] for r in rows
                  if r["case"].startswith(prefix) and r["case"].endswith(suffix)}
        hs = sorted(ladder, reverse=True)
        for h0, h1 in zip(hs, hs[1:]):
            print(f"{title}: first-order extrapolation from B/{1 / h0:.0f} and B/{1 / h1:.0f}: "
                  f"{2 * ladder[h1] - ladder[h0]:.3f}")
        data = os.path.join(a.out, f"prandtl_{prefix}{suffix}ladder.dat")
        with open(data, "w") as f:
            for h in hs:
                f.write(f"{h} {ladder[h]}\n")
        plots.append(f"{gp_quoted(data)} using 1:2 with linespoints pt 7 title {gp_quoted(title + ', 0.02 m/s')}")
    script = "\n".join([
        "set terminal pngcairo size 800,560",
        f"set output {gp_quoted(os.path.join(a.out, 'prandtl.png'))}",
        "set xlabel 'cell size h / B'",
        "set ylabel 'q / (2 + pi) s_u  (S/B 0.02-0.05; E = 10^4 s_u: 0.005-0.01)'",
        "set xrange [0:0.11]", "set yrange [0.9:1.25]", "set key top left", "set grid",
        "plot " + ", ".join(plots) + ", 1 with lines dt 2 lc rgb 'black' title 'Prandtl (2 + pi) s_u'", ""])
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    print(f"results: {a.out}/prandtl.csv, prandtl.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
