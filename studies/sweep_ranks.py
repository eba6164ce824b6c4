#!/usr/bin/env python3
"""How long a recorded sweep would take on more ranks, from its cases' own wall times
(docs/sweeps.md, "Several machines").

acst_sweep hands out whole cases, longest first by their expected work (particles x steps), each
to the first rank that is free (docs/sweeps.md, "Over MPI ranks"). This replays that schedule
with the wall time each case took in the recorded table (table.csv of a sweep's output folder,
one thread per case) for 1, 2, 4, ... ranks, and prints per rank count the estimated wall time,
its floor (the longest case, or the total over the ranks, whichever is larger) and the ranks'
mean use. The estimate holds where every rank runs its cases as fast as the recorded machine
did, one thread per case (a faster or slower core scales it; two ranks that share a core's
vector units do not).

  python3 studies/sweep_ranks.py data/sweeps/recorded/reference_study_local_0.09m/table.csv [--ranks 1,2,4,8,16,27]
"""
import argparse
import csv
import heapq
import sys


def schedule(cases, ranks):
    """The sweep's end (s) when CASES, [(expected work, wall s)], go longest first to the first free rank."""
    free = [0.0] * ranks
    heapq.heapify(free)
    for _, wall in sorted(cases, key=lambda c: -c[0]):
        heapq.heappush(free, heapq.heappop(free) + wall)
    return max(free)


def read_table(path):
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    cases = []
    for r in rows:
        try:
            cases.append((float(r["particles"]) * float(r["steps"]), float(r["wall_s"])))
        except (KeyError, ValueError):
            sys.exit(f"{path}: case {r.get('case', '?')} lacks particles, steps or wall_s")
        if r.get("threads") not in (None, "", "1"):
            print(f"note: case {r['case']} ran on {r['threads']} threads", file=sys.stderr)
    return cases


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("table")
    ap.add_argument("--ranks", default="1,2,4,8,16,27", help="comma-separated rank counts")
    a = ap.parse_args()
    cases = read_table(a.table)
    total, longest = sum(w for _, w in cases), max(w for _, w in cases)
    print(f"{len(cases)} cases, {total:.0f} s in all, the longest {longest:.0f} s")
    print("ranks  estimated wall time  floor     use")
    for n in (int(x) for x in a.ranks.split(",")):
        end = schedule(cases, n)
        print(f"{n:5d}  {end / 60:9.1f} min        {max(longest, total / n) / 60:5.1f} min  {100 * total / (n * end):4.0f} %")
    return 0


if __name__ == "__main__":
    sys.exit(main())
