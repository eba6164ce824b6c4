#!/usr/bin/env bash
# acst_sweep under mpirun: a two-case sweep on 2 ranks gives the table of the same sweep run in
# turn in one process, row for row, every column but wall time, threads and "resumed"; the log says
# that both ranks worked. Usage: sweep_mpi_test.sh ACST_SWEEP MPIEXEC SWEEP.json WORK_DIR
set -euo pipefail
tool=$1 mpiexec=$2 sweep=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
"$tool" --quiet --no-plot --threads 1 --output "$work/in_turn" "$sweep"
"$mpiexec" -n 2 "$tool" --no-plot --output "$work/ranks" "$sweep" 2>"$work/ranks.log"
grep -q "2 to run on 2 workers" "$work/ranks.log" || { echo "FAIL: the log does not say 2 workers:"; cat "$work/ranks.log"; exit 1; }

# The table without the columns that may differ between runs (found by name in the header).
strip() {
  awk -F, '/^#/ { next }
           !header { for (i = 1; i <= NF; i++) drop[i] = ($i == "wall_s" || $i == "threads" || $i == "resumed"); header = 1 }
           { line = ""; for (i = 1; i <= NF; i++) if (!drop[i]) line = line $i ","; print line }' "$1"
}
strip "$work/in_turn/table.csv" >"$work/in_turn.rows"
strip "$work/ranks/table.csv" >"$work/ranks.rows"
if ! diff "$work/in_turn.rows" "$work/ranks.rows"; then
  echo "FAIL: the tables differ"
  exit 1
fi
rows=$(grep -c ',done,' "$work/ranks.rows" || true)
[ "$rows" -eq 2 ] || { echo "FAIL: expected 2 cases done, found $rows"; cat "$work/ranks.rows"; exit 1; }
echo "PASS: 2 cases on 2 ranks, the same table as in turn"
