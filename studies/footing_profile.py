#!/usr/bin/env python3
"""Where the converged footing's time goes: data/scenes/mpm/kimura_V85.6_alpha0.json (the converged
default: micropolar rotations, graded grid, 0.045 m) run to S/B 0.05 (--quick: 0.01) on 1 and on 2
threads, each run's summary.json giving the wall time of every phase of the step
(step_phase_seconds, docs/mpm.md "Outputs"). Writes OUT/phases.csv (seconds and share per phase and
thread count, the phase's speed-up from 1 to 2 threads and the serial share that speed-up implies,
s = 2/speed-up - 1 by Amdahl's law) and OUT/phases.png. Run it on an otherwise idle machine: the
times are wall times. Results in bench/results/footing_profile/."""
import json
import os
import subprocess

from footing_common import ROOT, gp_quoted, run_study_case, scene_with_absolute_paths, study_arguments, write_table

SCENE = os.path.join(ROOT, "data", "scenes", "mpm", "kimura_V85.6_alpha0.json")


def main():
    a = study_arguments(__doc__, "footing_profile", "V85.6_threads1 and/or V85.6_threads2",
                        [("--quick", "run to S/B 0.01 only (a quick look)")])
    stop = 0.01 if a.quick else 0.05
    os.makedirs(a.out, exist_ok=True)
    summaries = {}
    for threads in (1, 2):
        name = f"V85.6_threads{threads}"

        def make_scene():
            s = scene_with_absolute_paths(SCENE)
            s["name"] = name
            s["stop"] = {"S_over_B": stop}
            s["solver"]["threads"] = threads
            s["output"].pop("particle_histories", None)
            s["output"]["vtk_every_S_over_B"] = stop
            s["output"]["contours_at_S_over_B"] = [stop]
            return s

        a.threads = threads
        run_study_case(a, name, make_scene)
        with open(os.path.join(a.out, name, "summary.json")) as f:
            summaries[threads] = json.load(f)
    one, two = (summaries[t]["step_phase_seconds"] for t in (1, 2))
    total1, total2 = sum(one.values()), sum(two.values())
    rows = []
    for phase in one:
        speedup = one[phase] / two[phase] if two[phase] > 0 else float("nan")
        serial = 2.0 / speedup - 1.0 if speedup == speedup else float("nan")
        rows.append([phase, f"{one[phase]:.3f}", f"{100 * one[phase] / total1:.1f}", f"{two[phase]:.3f}",
                     f"{100 * two[phase] / total2:.1f}", f"{speedup:.2f}", f"{serial:.2f}"])
    rows.append(["all phases", f"{total1:.3f}", "100", f"{total2:.3f}", "100", f"{total1 / total2:.2f}",
                 f"{2.0 * total2 / total1 - 1.0:.2f}"])
    fields = ["phase", "s_1_thread", "pct_1_thread", "s_2_threads", "pct_2_threads", "speedup", "serial_share"]
    write_table(os.path.join(a.out, "phases.csv"), fields, [dict(zip(fields, r)) for r in rows])
    data = os.path.join(a.out, "phases.dat")
    with open(data, "w") as f:
        for r in rows[:-1]:
            f.write(f"{r[0]} {r[1]} {r[3]}\n")
    steps = summaries[1]["steps"]
    script = "\n".join([
        "set terminal pngcairo size 1000,520 noenhanced", f"set output {gp_quoted(os.path.join(a.out, 'phases.png'))}",
        "set style data histogram", "set style histogram cluster gap 1", "set style fill solid 0.8 border -1",
        "set ylabel 'wall time, s'", "set xtics rotate by -30", "set key top right",
        f"set title 'Converged V85.6 to S/B {stop:g}: {steps} steps, {summaries[1]['particles']} particles; "
        f"{total1:.0f} s on 1 thread, {total2:.0f} s on 2'",
        f"plot {gp_quoted(data)} using 2:xtic(1) title '1 thread', '' using 3 title '2 threads'"])
    subprocess.run(["gnuplot"], input=script, text=True, check=False)
    print(f"1 thread {total1:.1f} s, 2 threads {total2:.1f} s ({total1 / total2:.2f}x); {os.path.join(a.out, 'phases.csv')}")


if __name__ == "__main__":
    main()
